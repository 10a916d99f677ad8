// Seed 003's residual V (§3.3) and its recomputation from positions alone.
#include "fabform/model/equilibrium.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fabform/model/model.hpp"
#include "support/shapes.hpp"

namespace fabform::equilibrium_test {
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

// A valley 120° wide along y: faces tilted 30° either way, normals n₁ = (−½, 0, √3/2) and
// n₂ = (½, 0, √3/2), the crease along t = y.
struct Valley {
  Eigen::Vector3d first{-0.5, 0.0, std::sqrt(3.0) / 2.0};
  Eigen::Vector3d second{0.5, 0.0, std::sqrt(3.0) / 2.0};
};

TEST(UnbalancedForceOnACrease, PressedIntoBothFacesOnlyThePartAlongTheCreaseIsLeft) {
  const Valley v;
  const Eigen::Vector3d r(0.1, 0.3, -1.0);  // down and a little towards the second face
  EXPECT_EQ(crease_hold(r, v.first, v.second), CreaseHold::both);
  EXPECT_NEAR((unbalanced_force(r, 0, &v.first, 0.0, &v.second) - Eigen::Vector3d(0.0, 0.3, 0.0)).norm(), 0.0, 1e-15);
  // The reaction is R less its part along y: |(0.1, 0, −1)|.
  EXPECT_NEAR(pressing_force(r, 0, v.first, &v.second), std::hypot(0.1, 1.0), 1e-15);
  // One face alone would leave its tangent-plane part, which pushes into the other face.
  EXPECT_GT(unbalanced_force(r, 0, &v.first).norm(), 0.3 + 0.1);
}

TEST(UnbalancedForceOnACrease, FrictionHoldsWithTheWholeReaction) {
  const Valley v;
  const double reaction = std::hypot(0.1, 1.0);
  EXPECT_EQ(unbalanced_force({0.1, 0.3, -1.0}, 0, &v.first, 0.4, &v.second), Eigen::Vector3d::Zero());
  const Eigen::Vector3d slipping = unbalanced_force({0.1, 0.8, -1.0}, 0, &v.first, 0.4, &v.second);
  EXPECT_NEAR(slipping.y(), 0.8 - 0.4 * reaction, 1e-15);
  EXPECT_NEAR(std::hypot(slipping.x(), slipping.z()), 0.0, 1e-15);
}

TEST(UnbalancedForceOnACrease, PullingOffOneFaceRestsOnTheOther) {
  const Valley v;
  const Eigen::Vector3d t = Eigen::Vector3d::UnitY();
  // R = −n₁ + ½ n₂ + 0.2 t pulls off the second face and presses on the first (R·n₁ = −¾).
  const Eigen::Vector3d off_second = -v.first + 0.5 * v.second + 0.2 * t;
  EXPECT_EQ(crease_hold(off_second, v.first, v.second), CreaseHold::first);
  EXPECT_EQ(unbalanced_force(off_second, 0, &v.first, 0.0, &v.second), unbalanced_force(off_second, 0, &v.first));
  const Eigen::Vector3d off_first = 0.5 * v.first - v.second;
  EXPECT_EQ(crease_hold(off_first, v.first, v.second), CreaseHold::second);
  EXPECT_EQ(unbalanced_force(off_first, 0, &v.first, 0.0, &v.second), unbalanced_force(off_first, 0, &v.second));
  EXPECT_EQ(pressing_force(off_first, 0, v.first, &v.second), pressing_force(off_first, 0, v.second));
  // Pulled off both, it is free.
  const Eigen::Vector3d up(0.0, 0.3, 1.0);
  EXPECT_EQ(crease_hold(up, v.first, v.second), CreaseHold::none);
  EXPECT_EQ(unbalanced_force(up, 0, &v.first, 0.0, &v.second), up);
}

TEST(UnbalancedForceOnACrease, ANodeHeldOnAnAxisIgnoresTheCrease) {
  const Valley v;
  const Eigen::Vector3d r(0.1, 0.3, -1.0);
  EXPECT_EQ(unbalanced_force(r, kLockX, &v.first, 0.0, &v.second), unbalanced_force(r, kLockX, &v.first));
  EXPECT_EQ(pressing_force(r, kLockX, v.first, &v.second), pressing_force(r, kLockX, v.first));
}

// Whatever R, held by both faces what is left lies along the crease and what the body takes is
// a push out of it along both normals; the rest rests on one face by the one-face rule.
TEST(UnbalancedForceOnACrease, RandomForcesSplitIntoTheCreaseAndACone) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d first = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    Eigen::Vector3d second = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    if (first.dot(second) > 0.99) continue;
    const Eigen::Vector3d r(normal(rng), normal(rng), normal(rng));
    const Eigen::Vector3d left = unbalanced_force(r, 0, &first, 0.0, &second);
    switch (crease_hold(r, first, second)) {
      case CreaseHold::both: {
        EXPECT_NEAR(left.dot(first), 0.0, 1e-12);
        EXPECT_NEAR(left.dot(second), 0.0, 1e-12);
        const Eigen::Vector3d taken = r - left;  // = a n₁ + b n₂, a, b ≤ 0
        const Eigen::Vector3d across = first.cross(second);
        EXPECT_NEAR(taken.dot(across), 0.0, 1e-12);
        const double c = first.dot(second);
        const double a = (taken.dot(first) - c * taken.dot(second)) / (1.0 - c * c);
        const double b = (taken.dot(second) - c * taken.dot(first)) / (1.0 - c * c);
        EXPECT_LE(a, 1e-12);
        EXPECT_LE(b, 1e-12);
        EXPECT_LE(left.norm(), r.norm() + 1e-12);
        break;
      }
      case CreaseHold::first: EXPECT_EQ(left, unbalanced_force(r, 0, &first)); break;
      case CreaseHold::second: EXPECT_EQ(left, unbalanced_force(r, 0, &second)); break;
      case CreaseHold::none: EXPECT_EQ(left, r); break;
    }
  }
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
}  // namespace fabform::equilibrium_test
