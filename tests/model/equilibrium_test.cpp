// Seed 003's residual V (§3.3) and its recomputation from positions alone.
#include "fabform/model/equilibrium.hpp"

#include <gtest/gtest.h>

#include "fabform/model/model.hpp"
#include "support/shapes.hpp"

namespace fabform {
namespace {

TEST(UnbalancedForce, FreeNodeKeepsAllOfR) {
  const Eigen::Vector3d r(1.0, -2.0, 3.0);
  EXPECT_EQ(unbalanced_force(r, 0, nullptr), r);
}

TEST(UnbalancedForce, LockedAxesCarryNoResidual) {
  const Eigen::Vector3d r(1.0, -2.0, 3.0);
  EXPECT_EQ(unbalanced_force(r, kLockX | kLockZ, nullptr), Eigen::Vector3d(0.0, -2.0, 0.0));
  EXPECT_EQ(unbalanced_force(r, kLockX | kLockY | kLockZ, nullptr), Eigen::Vector3d::Zero());
}

TEST(UnbalancedForce, ContactPressingInLeavesTheTangentialPart) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(unbalanced_force({0.5, 0.25, -4.0}, 0, &n), Eigen::Vector3d(0.5, 0.25, 0.0));
}

// Coulomb: the body holds up to μ·λ of the tangential part, λ = 4 N here; beyond, the excess
// is left, along the tangential part.
TEST(UnbalancedForce, FrictionHoldsTheTangentialPartWithinItsCone) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(unbalanced_force({0.6, 0.8, -4.0}, 0, &n, 0.25), Eigen::Vector3d::Zero());  // |R*| = 1 = μλ
  EXPECT_EQ(unbalanced_force({0.6, 0.8, -4.0}, 0, &n, 0.3), Eigen::Vector3d::Zero());
  const Eigen::Vector3d v = unbalanced_force({0.6, 0.8, -4.0}, 0, &n, 0.2);  // holds 0.8 of 1
  EXPECT_NEAR(v.x(), 0.2 * 0.6, 1e-15);
  EXPECT_NEAR(v.y(), 0.2 * 0.8, 1e-15);
  EXPECT_EQ(v.z(), 0.0);
  // Pulled off the body, friction holds nothing.
  EXPECT_EQ(unbalanced_force({0.6, 0.8, 4.0}, 0, &n, 0.3), Eigen::Vector3d(0.6, 0.8, 4.0));
}

// A lock's reaction takes R's part along its axis, so only the free part of R presses on the
// body: held in z on a horizontal body, nothing presses and nothing is held by friction.
TEST(UnbalancedForce, FrictionPressesOnlyWithTheFreePartOfR) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(unbalanced_force({0.6, 0.8, -4.0}, kLockZ, &n, 0.3), Eigen::Vector3d(0.6, 0.8, 0.0));
}

TEST(UnbalancedForce, ContactPullingOutKeepsAllOfR) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(unbalanced_force({0.5, 0.25, 4.0}, 0, &n), Eigen::Vector3d(0.5, 0.25, 4.0));
}

// A 3 × 3 node patch whose centre node sits at height z over a sphere whose top is at z = 0
// below it; the other nodes sit 0.5 mm lower, so the springs pull the centre down.
// A node held in x and y on a slope can only move in z, which the surface blocks: no residual.
TEST(UnbalancedForce, LockedNodeOnASlopeIsBalancedByTheSurface) {
  const Eigen::Vector3d n = Eigen::Vector3d(0.6, 0.0, 0.8);
  EXPECT_NEAR(unbalanced_force({0.0, 0.0, -1.0}, kLockX | kLockY, &n).norm(), 0.0, 1e-15);
  // Held in y only, it slides along the slope's fall line in x and z.
  const Eigen::Vector3d r(0.3, 0.7, -1.0);
  const Eigen::Vector3d v = unbalanced_force(r, kLockY, &n);
  EXPECT_EQ(v.y(), 0.0);
  EXPECT_NEAR(v.dot(n), 0.0, 1e-15);
  EXPECT_NEAR(v.x(), 0.3 - (0.3 * 0.6 - 0.8) * 0.6, 1e-15);
}

Model two_by_two_over_sphere(double z) {
  Fabric grid({0.02, 0.02, 2, 2});
  std::vector<Eigen::Vector3d> x(9);
  for (int k = 0; k < 9; ++k) x[static_cast<std::size_t>(k)] = grid.rest_position(k) - Eigen::Vector3d(0, 0, 5e-4);
  x[4].z() = z;
  const TensionTable table({{0.0, 0.0}, {1.0, 100.0}});
  Model model{grid, table, table, std::vector<AxisMask>(9, 0), {}, x};
  model.bodies.emplace_back("sphere", test::uv_sphere({0.01, 0.01, -0.05}, 0.05, 60, 120));
  return model;
}

// The centre node sits on the sphere's top with the four springs pulling it down: in contact,
// its residual is the tangential part only, which vanishes by symmetry; free, it would be |R|.
TEST(MeasureEquilibrium, ContactNodeOnTopOfSphere) {
  const Model model = two_by_two_over_sphere(0.0);
  const EquilibriumReport report = measure_equilibrium(model, model.start, 1e-9);
  EXPECT_EQ(report.contact[4], 1);
  EXPECT_EQ(report.contact_nodes, 1);
  EXPECT_GT(unbalanced_force(node_force(model, model.start, 4), 0, nullptr).norm(), 1e-5);
  // Symmetric springs: the tangential force cancels to rounding (forces are ~1 N).
  EXPECT_NEAR(report.residual_N[4], 0.0, 1e-12);
  EXPECT_EQ(report.max_penetration_m, 0.0);
}

TEST(MeasureEquilibrium, NodeInsideIsReportedAsPenetration) {
  const Model model = two_by_two_over_sphere(-0.001);
  const EquilibriumReport report = measure_equilibrium(model, model.start, 1e-9);
  // The sphere is tessellated, so the depth is 1 mm less at most the facets' sag (< 0.1 mm).
  EXPECT_NEAR(report.max_penetration_m, 0.001, 1e-4);
}

TEST(MeasureEquilibrium, NonFiniteNodeGivesNaN) {
  Model model = two_by_two_over_sphere(0.0);
  model.start[3].x() = std::numeric_limits<double>::infinity();
  const EquilibriumReport report = measure_equilibrium(model, model.start, 1e-9);
  EXPECT_TRUE(std::isnan(report.max_residual_N));
  EXPECT_EQ(report.worst_node, 3);
}

}  // namespace
}  // namespace fabform
