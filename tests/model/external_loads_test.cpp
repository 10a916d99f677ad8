// The fabric's weight: each node carries its own area's, the whole fabric weighs ρ·g·W·H, and
// the loads' potential −Σ f·x is what they do work against.
#include "fabform/model/external_loads.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace fabform {
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

// The potential of constant loads is linear: its finite differences are exact up to rounding,
// and equal minus the load at each node and axis.
TEST(LoadEnergy, ItsGradientIsMinusTheLoads) {
  const Fabric grid({0.1, 0.1, 3, 3});
  const std::vector<Eigen::Vector3d> loads = gravity_loads(grid, 0.2, 9.81);
  std::mt19937 rng(7u);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < grid.node_count(); ++k)
    x.push_back(grid.rest_position(k) + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)));
  const double h = 1e-4;  // m; exact for a linear function up to the rounding of E ± f·h
  for (std::size_t k = 0; k < x.size(); ++k)
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<Eigen::Vector3d> plus = x, minus = x;
      plus[k][axis] += h, minus[k][axis] -= h;
      const double slope = (load_energy(loads, plus) - load_energy(loads, minus)) / (2 * h);
      EXPECT_NEAR(slope, -loads[k][axis], 1e-9 * loads[0].norm()) << k << " " << axis;
    }
}

TEST(LoadEnergy, ItsChangeIsTheDifferenceOfItsValues) {
  const Fabric grid({0.1, 0.1, 3, 3});
  const std::vector<Eigen::Vector3d> loads = gravity_loads(grid, 0.2, 9.81);
  std::vector<Eigen::Vector3d> from, to;
  for (int k = 0; k < grid.node_count(); ++k) {
    from.push_back(grid.rest_position(k));
    to.push_back(grid.rest_position(k) + Eigen::Vector3d(0.001 * k, -0.002, -0.003 * k));
  }
  const double change = load_energy_change(loads, from, to);
  ASSERT_TRUE(std::isfinite(change) && change != 0.0);
  EXPECT_NEAR(change, load_energy(loads, to) - load_energy(loads, from), 1e-12 * std::abs(change));
  EXPECT_EQ(load_energy_change(loads, from, from), 0.0);
}

// e must be well below a node's weight, or a run may stop before the weight shows.
TEST(LoadToleranceWarning, WhenTheToleranceIsNotWellBelowTheLightestNodesWeight) {
  const Fabric grid({0.1, 0.1, 40, 40});  // seed 003's mold grid
  const std::vector<Eigen::Vector3d> loads = gravity_loads(grid, 0.204, kStandardGravity_m_s2);
  const double corner = 0.204 * 0.0025 * 0.0025 / 4 * kStandardGravity_m_s2;  // ~3.1e-6 N
  const std::string warning = load_tolerance_warning(loads, 1e-3);
  EXPECT_NE(warning.find("e = 0.001 N"), std::string::npos) << warning;
  EXPECT_NE(warning.find("lightest node's weight (3.13e-06 N)"), std::string::npos) << warning;
  EXPECT_EQ(load_tolerance_warning(loads, 0.1 * corner), "") << "just below the bound";
  EXPECT_NE(load_tolerance_warning(loads, 0.1 * corner * (1 + 1e-12)), "");
  EXPECT_EQ(load_tolerance_warning({}, 1.0), "") << "no loads";
}

TEST(LoadEnergy, NoLoadsNoEnergy) {
  EXPECT_EQ(load_energy({}, {Eigen::Vector3d(1, 2, 3)}), 0.0);
}

}  // namespace
}  // namespace fabform
