// A blank holder against Coulomb's law: a strip gripped over its first columns by a holder of
// force F (μ on both faces) and pulled at its other end by δ. Once every gripped node slides,
// each column k resists with f_k = 2μF·a_k/Σa, the strip's tension grows column by column to
// 2μF past the holder, and every spring's strain is its tension over the strip's stiffness:
// so the edge's draw-in is known in closed form. A pull below 2μF in all draws nothing in
// beyond the creep length.
#include <gtest/gtest.h>

#include <memory>

#include "fabform/model/clamp_frame.hpp"
#include "fabform/solver/solve.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::clamp_draw_in_test {
namespace {

constexpr double kLength_m = 0.2;
constexpr double kWidth_m = 0.01;
constexpr int kColumns = 40;  // springs along the strip
constexpr int kGripped = 5;   // columns 0..5 under the holder
constexpr double kStiffness_N_m = 500.0;
constexpr double kMu = 0.3;
constexpr double kCreep_m = 1e-6;

struct PulledStrip {
  Model model;
  const ClampFrame* clamp = nullptr;

  PulledStrip(double force_N, double pull_m) : model(build(pull_m)) {
    std::vector<int> gripped;
    for (int k = 0; k < model.node_count(); ++k)
      if (model.fabric.i_of(k) <= kGripped) gripped.push_back(k);
    auto holder = std::make_shared<ClampFrame>(model.fabric, gripped, ClampOptions{force_N, kMu, kCreep_m}, model.start);
    clamp = holder.get();
    model.terms.push_back(holder);
  }

  // A plane problem along x: every node held in y and z, the far column in x too, pulled by δ.
  static Model build(double pull_m) {
    Fabric strip({kLength_m, kWidth_m, kColumns, 1});
    std::vector<AxisMask> locks(static_cast<std::size_t>(strip.node_count()), kLockY | kLockZ);
    std::vector<Eigen::Vector3d> start;
    for (int k = 0; k < strip.node_count(); ++k) {
      start.push_back(strip.rest_position(k));
      if (strip.i_of(k) == kColumns) {
        locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
        start.back().x() += pull_m;
      }
    }
    return Model{strip, test::linear_table(kStiffness_N_m), test::linear_table(kStiffness_N_m), locks, {}, start};
  }

  // Where column 0 ends when every gripped column slides: walk the tension from the edge.
  double closed_form_draw_in(double force_N, double pull_m) const {
    const Fabric& f = model.fabric;
    std::vector<double> column_area(kColumns + 1, 0.0);
    double gripped_area = 0.0;
    for (int k = 0; k < f.node_count(); ++k) {
      column_area[static_cast<std::size_t>(f.i_of(k))] += f.node_areas()[static_cast<std::size_t>(k)];
      if (f.i_of(k) <= kGripped) gripped_area += f.node_areas()[static_cast<std::size_t>(k)];
    }
    const double h = kLength_m / kColumns;
    double tension = 0.0, length = 0.0;
    for (int i = 0; i < kColumns; ++i) {
      if (i <= kGripped) tension += 2.0 * kMu * force_N * column_area[static_cast<std::size_t>(i)] / gripped_area;
      length += h * (1.0 + tension / (kWidth_m * kStiffness_N_m));
    }
    return kLength_m + pull_m - length;
  }
};

Summary solve_strip(PulledStrip& strip, SolverState& state) {
  SolverSpec spec;
  spec.name = "newton";
  spec.newton.tolerance_N = 1e-11;
  return solve(strip.model, state, spec);
}

TEST(ClampDrawIn, APullBeyondTwiceMuFDrawsTheEdgeInAsCoulombSays) {
  const double force_N = 0.5, pull_m = 0.03;  // 2μF = 0.3 N: the free strip at 6 % strain
  PulledStrip strip(force_N, pull_m);
  SolverState state = SolverState::at_start(strip.model);
  const Summary s = solve_strip(strip, state);
  ASSERT_TRUE(s.converged()) << s.message;
  const double expected = strip.closed_form_draw_in(force_N, pull_m);
  ASSERT_GT(expected, 100.0 * kCreep_m);
  // Column 0's nodes are the strip's corners, whose draw-in draw_in.hpp takes along their
  // diagonal; along the strip it is their move in x. The creep length is the model's own error.
  for (int k = 0; k < strip.model.node_count(); ++k)
    if (strip.model.fabric.i_of(k) == 0) {
      EXPECT_NEAR(state.x[static_cast<std::size_t>(k)].x(), expected, 2.0 * kCreep_m) << k;
      EXPECT_FALSE(strip.clamp->stuck(k, state.x[static_cast<std::size_t>(k)]));
    }
}

TEST(ClampDrawIn, APullBelowTwiceMuFDrawsNothingIn) {
  const double force_N = 50.0, pull_m = 0.002;  // 2μF = 30 N; the pull needs 0.5 N
  PulledStrip strip(force_N, pull_m);
  SolverState state = SolverState::at_start(strip.model);
  ASSERT_TRUE(solve_strip(strip, state).converged());
  for (int k = 0; k < strip.model.node_count(); ++k)
    if (strip.model.fabric.i_of(k) == 0) {
      EXPECT_LT(std::abs(state.x[static_cast<std::size_t>(k)].x()), kCreep_m) << k;
    }
}

}  // namespace
}  // namespace fabform::clamp_draw_in_test
