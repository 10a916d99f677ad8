// The fabric's weight: each node carries its own area's, the whole fabric weighs ρ·g·W·H, and
// the loads' potential −Σ f·x is what they do work against.
#include "fabform/model/gravity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "support/clamped_fabric.hpp"
#include "support/term_checks.hpp"

namespace fabform::gravity_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(GravityLoads, TheWholeFabricWeighsDensityTimesAreaTimesG) {
  const Fabric grid({0.3, 0.2, 6, 4});
  const double density = 0.324, g = 9.81;
  const std::vector<Eigen::Vector3d> loads = gravity_loads(grid, density, g);
  ASSERT_EQ(loads.size(), static_cast<std::size_t>(grid.node_count()));
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const auto& f : loads) total += f;
  const double weight = density * 0.3 * 0.2 * g;
  EXPECT_NEAR(total.z(), -weight, 8.0 * grid.node_count() * kEps * weight);
  EXPECT_EQ(total.x(), 0.0);
  EXPECT_EQ(total.y(), 0.0);
  const double cell_weight = density * 0.05 * 0.05 * g;  // an inner node
  EXPECT_NEAR(loads[static_cast<std::size_t>(grid.node(3, 2))].z(), -cell_weight, 8.0 * kEps * cell_weight);
  EXPECT_NEAR(loads[static_cast<std::size_t>(grid.node(0, 0))].z(), -cell_weight / 4, 8.0 * kEps * cell_weight);
  EXPECT_NEAR(loads[static_cast<std::size_t>(grid.node(0, 2))].z(), -cell_weight / 2, 8.0 * kEps * cell_weight);
}

Positions jittered(const Fabric& grid, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  Positions x;
  for (int k = 0; k < grid.node_count(); ++k)
    x.push_back(grid.rest_position(k) + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)));
  return x;
}

// The potential of constant loads is linear: its finite differences are exact up to the
// rounding of E ± f·h, and equal minus the load at each node and axis. It has no stiffness.
TEST(Gravity, ItsForceIsMinusTheGradientOfItsPotential) {
  const Model model = test::clamped_fabric(3);
  const Gravity gravity(model.fabric, 0.2, 9.81);
  const Positions x = jittered(model.fabric, 7u);
  test::expect_force_is_minus_the_gradient(model, gravity, x, 1e-4, 1e-9);
  for (int k = 0; k < model.node_count(); ++k)
    EXPECT_EQ(gravity.force_at(model, x, k, Eigen::Vector3d(1, 2, 3)), gravity.loads()[static_cast<std::size_t>(k)]);
  EXPECT_EQ(test::dense_stiffness(model, gravity, x).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_TRUE(gravity.external());
}

TEST(Gravity, ItsChangesAreTheDifferencesOfItsValues) {
  const Model model = test::clamped_fabric(3);
  const Gravity gravity(model.fabric, 0.2, 9.81);
  test::expect_node_changes_are_the_whole(model, gravity, jittered(model.fabric, 8u), {0, 5, 15},
                                          Eigen::Vector3d(0.001, -0.002, -0.003));
}

// Far above the origin, the change computed from the moves keeps the digits a difference of
// two absolute potentials (~m·g·z) loses.
TEST(Gravity, ItsChangeKeepsItsDigitsHighUp) {
  const Model model = test::clamped_fabric(3);
  const Gravity gravity(model.fabric, 0.2, 9.81);
  Positions from = jittered(model.fabric, 9u), to = from;
  for (auto& p : from) p.z() += 1e6;
  to = from;
  to[5].z() -= 1e-9;
  const double exact = -gravity.loads()[5].z() * (to[5].z() - from[5].z());  // −f·Δx: Π falls
  const double before = gravity.energy(model, from);
  EXPECT_NEAR(gravity.energy_change(model, from, before, to), exact, 1e-12 * std::abs(exact));
  EXPECT_GT(std::abs(gravity.energy(model, to) - before - exact), 1e-3 * std::abs(exact))
      << "a difference of potentials would have lost the change";
}

// e must be well below a node's weight, or a run may stop before the weight shows.
TEST(Gravity, WarnsWhenTheToleranceIsNotWellBelowTheLightestNodesWeight) {
  const Fabric grid({0.1, 0.1, 40, 40});  // seed 003's mold grid
  const Gravity gravity(grid, 0.204, kStandardGravity_m_s2);
  const double corner = 0.204 * 0.0025 * 0.0025 / 4 * kStandardGravity_m_s2;  // ~3.1e-6 N
  const std::string warning = gravity.tolerance_warning(1e-3);
  EXPECT_NE(warning.find("e = 0.001 N"), std::string::npos) << warning;
  EXPECT_NE(warning.find("lightest node's weight (3.13e-06 N)"), std::string::npos) << warning;
  EXPECT_EQ(gravity.tolerance_warning(0.1 * corner), "") << "just below the bound";
  EXPECT_NE(gravity.tolerance_warning(0.1 * corner * (1 + 1e-12)), "");
}

}  // namespace
}  // namespace fabform::gravity_test
