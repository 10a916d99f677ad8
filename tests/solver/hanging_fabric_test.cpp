// Every solver on a fabric hanging under its own weight from its top edge, against the exact
// rest of the discrete model: the weft spring between rows j and j + 1 (j = 0 at the top)
// carries the weight of the rows below it, ρ·g·h·(m − j − 3/2) per unit width (the bottom row
// stands for half a row), so with a linear table T = k·ε its strain is that over k. Rows stay
// level (every column carries the same weight per width), so the rest is this chain exactly.
#include <gtest/gtest.h>

#include <memory>

#include <string>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/gravity.hpp"
#include "fabform/solver/solve.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::hanging_fabric_test {
namespace {

constexpr double kDensity_kg_m2 = 0.2;
constexpr double kStiffness_N_m = 5.0;  // the top springs stretch by ~4 %

// A 10 × 10 cm fabric hanging in the x-z plane: weft (j) runs down, top row locked.
Model hanging_fabric(int divisions_warp, int divisions_weft) {
  Fabric grid({0.1, 0.1, divisions_warp, divisions_weft});
  std::vector<AxisMask> locks(static_cast<std::size_t>(grid.node_count()), 0);
  std::vector<Eigen::Vector3d> start(static_cast<std::size_t>(grid.node_count()));
  for (int k = 0; k < grid.node_count(); ++k) {
    const Eigen::Vector3d rest = grid.rest_position(k);
    start[static_cast<std::size_t>(k)] = Eigen::Vector3d(rest.x(), 0.0, -rest.y());
    if (grid.j_of(k) == 0) locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
  }
  Model model{grid, test::linear_table(kStiffness_N_m), test::linear_table(kStiffness_N_m), locks, {}, start};
  model.terms.push_back(std::make_shared<Gravity>(grid, kDensity_kg_m2, kStandardGravity_m_s2));
  return model;
}

// z of each row at rest, from the strains of the springs above it.
std::vector<double> exact_row_heights(const Fabric& grid) {
  const int m = grid.nodes_weft();
  const double h = grid.spacing_weft();
  std::vector<double> z(static_cast<std::size_t>(m), 0.0);
  for (int j = 0; j + 1 < m; ++j) {
    const double tension = kDensity_kg_m2 * kStandardGravity_m_s2 * h * (m - j - 1.5);
    z[static_cast<std::size_t>(j + 1)] = z[static_cast<std::size_t>(j)] - h * (1.0 + tension / kStiffness_N_m);
  }
  return z;
}

class HangingFabric : public ::testing::TestWithParam<std::string> {};

TEST_P(HangingFabric, StretchesAsTheWeightBelowEachSpringSays) {
  const Model model = hanging_fabric(4, 10);
  SolverSpec spec;
  spec.name = GetParam();
  // A node weighs ~5e-4 N; 1e-10 N leaves positions within ~1e-10 m of the rest.
  const double tolerance_N = 1e-10;
  spec.relax.tolerance_N = spec.newton.tolerance_N = spec.dynamic.tolerance_N = tolerance_N;
  spec.relax.max_iterations = 200000;
  spec.dynamic.max_iterations = 2000000;
  SolverState state = SolverState::at_start(model);
  const Summary summary = solve(model, state, spec);
  ASSERT_TRUE(summary.converged()) << summary.message;
  EXPECT_LE(measure_equilibrium(model, state.x, 1e-9).max_residual_N, 10 * tolerance_N);

  const std::vector<double> z = exact_row_heights(model.fabric);
  const double total_stretch = -z.back() - 0.1;  // ~2 mm
  ASSERT_GT(total_stretch, 1e-3);
  // Down the fabric the springs' stiffness is ≥ w·k/h ≈ 6 N/m, so e leaves z within ~1e-10 m;
  // 1e-6 of the stretch is ~2e-9 m. Sideways only the weft tension holds a node, T·w/h, which
  // at the bottom row is ~0.01 N/m: e allows ~1e-8 m there.
  const double lateral_m = 5.0 * tolerance_N / 0.01;
  for (int k = 0; k < model.node_count(); ++k) {
    const Eigen::Vector3d& p = state.x[static_cast<std::size_t>(k)];
    EXPECT_NEAR(p.z(), z[static_cast<std::size_t>(model.fabric.j_of(k))], 1e-6 * total_stretch) << "node " << k;
    EXPECT_NEAR(p.x(), model.fabric.rest_position(k).x(), lateral_m) << "node " << k;
    EXPECT_NEAR(p.y(), 0.0, lateral_m) << "node " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(EverySolver, HangingFabric, ::testing::Values("relax", "dynamic", "newton"),
                         [](const auto& case_info) { return case_info.param; });

}  // namespace
}  // namespace fabform::hanging_fabric_test
