// The distance from the rest the solvers report, on a problem whose rest is known exactly: a
// chain of linear springs stretched 20 % between held ends and moved along itself only, so that
// its forces are linear in the positions and its rest is the evenly spaced chain; and on the
// dome, against newton's rest at 1e-12 N.
#include "fabform/solver/position_error.hpp"

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "fabform/solver/dynamic.hpp"
#include "fabform/solver/newton.hpp"
#include "fabform/solver/relax.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "support/clamped_fabric.hpp"
#include "test_paths.hpp"

namespace fabform::position_error_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Chain {
  Model model;
  std::vector<Eigen::Vector3d> rest;  // the exact rest
};

// A 10 cm fabric of `divisions` × 2 cells, stretched 20 % along x. The middle row is the chain:
// held in y and z, its ends held whole; the other rows are held whole. The weft springs carry
// nothing (a table of zero tension), so a chain node feels its two warp springs alone.
Chain stretched_chain(int divisions) {
  const Fabric grid({0.1, 0.1, divisions, 2});
  std::vector<AxisMask> locks(static_cast<std::size_t>(grid.node_count()), kLockX | kLockY | kLockZ);
  std::vector<Eigen::Vector3d> x(static_cast<std::size_t>(grid.node_count()));
  for (int k = 0; k < grid.node_count(); ++k) {
    x[static_cast<std::size_t>(k)] = grid.rest_position(k);
    x[static_cast<std::size_t>(k)].x() *= 1.2;
  }
  for (int i = 1; i < divisions; ++i) locks[static_cast<std::size_t>(grid.node(i, 1))] = kLockY | kLockZ;
  const TensionTable none({{0.0, 0.0}, {1.0, 0.0}}, "none");
  Model model(grid, test::linear_table(500.0), none, locks, {}, x);
  return {std::move(model), x};
}

// The chain's nodes moved along it by `shape(i)` (m): the distance from the rest is known.
double displace(Chain& chain, int divisions, double (*shape)(int, int)) {
  double largest = 0.0;
  for (int i = 1; i < divisions; ++i) {
    const double d = shape(i, divisions);
    chain.model.start[static_cast<std::size_t>(chain.model.fabric.node(i, 1))].x() += d;
    largest = std::max(largest, std::abs(d));
  }
  return largest;
}

// A smooth error, the slowest mode of the chain, 1 mm at its middle.
double smooth(int i, int n) { return 1e-3 * std::sin(kPi * i / n); }

TEST(LargestMove, IsTheLongestNodeMove) {
  EXPECT_EQ(largest_move({}), 0.0);
  EXPECT_DOUBLE_EQ(largest_move({{3e-3, 4e-3, 0.0}, {0.0, 0.0, -2e-3}}), 5e-3);
  EXPECT_DOUBLE_EQ(largest_move({{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}}, {{1.0, 1.0, 1.0}, {0.0, 3e-3, 4e-3}}), 5e-3);
}

// On a linear problem Newton's step is the exact way to the rest: the estimate of a run stopped
// before its first step is the distance itself (to the regularisation's 1e-8).
TEST(PositionError, NewtonStepIsTheExactDistanceOnALinearProblem) {
  const int n = 20;
  Chain chain = stretched_chain(n);
  const double distance = displace(chain, n, smooth);
  SolverState state = SolverState::at_start(chain.model);
  NewtonOptions options;
  options.tolerance_N = 1e-12;
  options.max_iterations = 0;
  const Summary s = newton(chain.model, state, options);
  EXPECT_EQ(s.termination, Termination::not_converged);
  EXPECT_NEAR(s.position_error_m, distance, 1e-6 * distance);
}

// The distance tolerance stops the run where the estimate falls within it, whichever tolerance
// comes first: here one Newton step lands on the rest, and the next step's size (rounding) says so.
TEST(PositionError, NewtonStopsOnTheDistanceTolerance) {
  const int n = 20;
  Chain chain = stretched_chain(n);
  displace(chain, n, smooth);
  SolverState state = SolverState::at_start(chain.model);
  NewtonOptions options;
  options.tolerance_N = 1e-300;  // never met: the distance alone stops the run
  options.tolerance_m = 1e-9;
  const Summary s = newton(chain.model, state, options);
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_EQ(s.converged_on, StopCriterion::position);
  EXPECT_LE(s.position_error_m, 1e-9);
  EXPECT_EQ(s.iterations, 1);
  for (int i = 1; i < n; ++i) {
    const auto k = static_cast<std::size_t>(chain.model.fabric.node(i, 1));
    EXPECT_NEAR(state.x[k].x(), chain.rest[k].x(), 1e-9);
  }
}

// A geometric tail, ‖V‖∞ falling by ρ each iteration: the moves still to come sum to Δ·ρ/(1 − ρ).
TEST(RatePositionError, IsTheRestOfAGeometricSeries) {
  std::vector<IterationRecord> history;
  for (int k = 0; k <= 60; ++k) history.push_back({k, 2.0 * std::pow(0.9, k), 0.0, 0, 0});
  EXPECT_NEAR(rate_position_error(history, 1e-3), 1e-3 * 0.9 / 0.1, 1e-12);
  history.resize(5);  // a short history: ρ over half of it
  EXPECT_NEAR(rate_position_error(history, 1e-3), 9e-3, 1e-12);
}

// newton's steps in a linear tail, each half the last: the steps still to come sum to twice the
// next one; one step alone is the estimate (the quadratic end, or a linear problem).
TEST(NewtonPositionError, IsTheNextStepOverOneLessTheRate) {
  std::vector<double> sizes;
  for (int k = 0; k < 15; ++k) sizes.push_back(1e-3 * std::pow(0.5, k));
  EXPECT_NEAR(newton_position_error(sizes), 2.0 * sizes.back(), 1e-15);
  EXPECT_DOUBLE_EQ(newton_position_error({4e-6}), 4e-6);
  EXPECT_TRUE(std::isnan(newton_position_error({})));
  EXPECT_TRUE(std::isnan(newton_position_error({1e-6, 2e-6})));  // the steps grow: no figure
}

// A loose Newton's tail, ‖V‖∞ halving each iteration: the tight step δ and the steps still to
// come sum to δ/(1 − ρ) = 2δ; no figure while ‖V‖∞ rises.
TEST(InexactNewtonPositionError, IsTheTightStepOverOneLessTheResidualRate) {
  std::vector<IterationRecord> history;
  for (int k = 0; k <= 30; ++k) history.push_back({k, std::pow(0.5, k), 0.0, 0, 0});
  EXPECT_NEAR(inexact_newton_position_error(1e-6, history), 2e-6, 1e-15);
  history.push_back({31, 1.0, 0.0, 0, 0});
  EXPECT_TRUE(std::isnan(inexact_newton_position_error(1e-6, history)));
}

TEST(RatePositionError, HasNoFigureWithoutAFallingResidual) {
  std::vector<IterationRecord> history{{0, 1.0, 0.0, 0, 0}, {1, 0.5, 0.0, 0, 0}};
  EXPECT_TRUE(std::isnan(rate_position_error(history, 1e-3)));  // under two iterations of ρ
  history.push_back({2, 0.6, 0.0, 0, 0});
  history.push_back({3, 0.7, 0.0, 0, 0});
  history.push_back({4, 1.2, 0.0, 0, 0});
  EXPECT_TRUE(std::isnan(rate_position_error(history, 1e-3)));  // rising
}

// relax and dynamic on the chain, stopped loosely: relax's estimate is within a factor of 3 of
// the distance from the exact rest; dynamic's within 3 below and 5 above, as near critical
// damping its moves swing to and fro and their sum overstates the distance (3.9 times here at
// 1e-4 N; 0.8 to 1.05 on the dome). Asked for a distance, relax stops within it.
TEST(RatePositionError, RelaxAndDynamicOnALinearProblemAreWithinAFactorOfThree) {
  const int n = 20;
  Chain chain = stretched_chain(n);
  displace(chain, n, smooth);
  const auto distance = [&](const SolverState& s) {
    double largest = 0.0;
    for (std::size_t k = 0; k < s.x.size(); ++k) largest = std::max(largest, (s.x[k] - chain.rest[k]).norm());
    return largest;
  };
  for (const double e : {1e-2, 1e-4}) {
    SolverState relaxed = SolverState::at_start(chain.model);
    RelaxOptions r;
    r.tolerance_N = e;
    const Summary by_relax = relax(chain.model, relaxed, r);
    ASSERT_EQ(by_relax.converged_on, StopCriterion::force) << by_relax.message;
    EXPECT_TRUE(by_relax.position_error_m >= distance(relaxed) / 3 && by_relax.position_error_m <= 3 * distance(relaxed))
        << "relax, e = " << e << ": estimate " << by_relax.position_error_m << ", distance " << distance(relaxed);
    SolverState moved = SolverState::at_start(chain.model);
    DynamicOptions d;
    d.tolerance_N = e;
    const Summary by_dynamic = dynamic(chain.model, moved, d);
    ASSERT_EQ(by_dynamic.converged_on, StopCriterion::force) << by_dynamic.message;
    EXPECT_TRUE(by_dynamic.position_error_m >= distance(moved) / 3 && by_dynamic.position_error_m <= 5 * distance(moved))
        << "dynamic, e = " << e << ": estimate " << by_dynamic.position_error_m << ", distance " << distance(moved);
  }
  SolverState relaxed = SolverState::at_start(chain.model);
  RelaxOptions r;
  r.tolerance_N = 1e-300;
  r.tolerance_m = 1e-6;
  const Summary by_relax = relax(chain.model, relaxed, r);
  ASSERT_EQ(by_relax.converged_on, StopCriterion::position) << by_relax.message;
  EXPECT_LE(by_relax.position_error_m, 1e-6);
  EXPECT_LE(distance(relaxed), 3e-6);
}

double largest_distance(const SolverState& a, const SolverState& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.x.size(); ++i) largest = std::max(largest, (a.x[i] - b.x[i]).norm());
  return largest;
}

// Newton on the dome of `divisions` × `divisions` cells, with the scene's options but the linear
// solve and the tolerances. On the exact matrix (no slack floor): a run stopped in metres takes
// it, so the reference it is measured from must follow the same path.
class DomeRuns {
 public:
  DomeRuns(int divisions, const std::string& linear_solver)
      : scene_(load_scene(test::source_path("scenes/dome.toml"),
                          {{"fabric.divisions", "[" + std::to_string(divisions) + "," + std::to_string(divisions) + "]"},
                           {"solver.linear_solver", "\"" + linear_solver + "\""},
                           {"solver.slack_stiffness", "0"}})),
        model_(build_model(scene_)) {}

  /// Where exact Newton steps (the factorisation) take `from`, to 1e-12 N.
  SolverState exact_rest_from(SolverState from) const {
    NewtonOptions options = scene_.solver.newton;
    options.linear_solver = "cholesky";
    options.tolerance_N = 1e-12;
    const Summary summary = newton(model_, from, options);
    EXPECT_TRUE(summary.converged()) << summary.message;
    return from;
  }

  SolverState solve_to(double tolerance_N, double tolerance_m, Summary* summary) const {
    SolverState state = SolverState::at_start(model_);
    NewtonOptions options = scene_.solver.newton;
    options.tolerance_N = tolerance_N;
    options.tolerance_m = tolerance_m;
    *summary = newton(model_, state, options);
    EXPECT_TRUE(summary->converged()) << summary->message;
    return state;
  }

 private:
  Scene scene_;
  Model model_;
};

// Newton stopped at each loose e is as far from `reference` as its estimate says, within a
// factor of 3.
void expect_estimates_within_three(const DomeRuns& dome, const SolverState& reference, std::initializer_list<double> es) {
  for (const double e : es) {
    Summary s;
    const SolverState loose = dome.solve_to(e, 0.0, &s);
    const double measured = largest_distance(loose, reference);
    EXPECT_EQ(s.converged_on, StopCriterion::force);
    EXPECT_TRUE(s.position_error_m >= measured / 3 && s.position_error_m <= 3 * measured)
        << "e = " << e << " N: estimate " << s.position_error_m << " m, measured " << measured << " m";
  }
}

// Against something independent, on the dome at 41 × 41 nodes (contact, a curved rest): newton
// stopped at a loose e, or at a distance tolerance, is as far from newton's rest at 1e-12 N (the
// reference, the same path's end) as its estimate says, within a factor of 3.
TEST(PositionError, NewtonEstimateOnTheDomeIsWithinAFactorOfThreeOfTheMeasuredDistance) {
  const DomeRuns dome(40, "cholesky");
  Summary s;
  const SolverState reference = dome.solve_to(1e-12, 0.0, &s);
  expect_estimates_within_three(dome, reference, {1e-2, 1e-3, 1e-4, 1e-5});
  for (const double tolerance_m : {1e-4, 1e-6}) {
    const SolverState stopped = dome.solve_to(1e-300, tolerance_m, &s);
    EXPECT_EQ(s.converged_on, StopCriterion::position);
    EXPECT_LE(largest_distance(stopped, reference), 3 * tolerance_m) << tolerance_m << " m";
  }
}

// Inexact Newton's loose steps (conjugate gradients to η up to 0.1) are far shorter than the way
// to the rest: on the dome at 81 × 81 nodes the estimate read from their sizes was null at 1e-5 N
// and 14 times the measured distance at 1e-6 N. It comes instead from one tight step and the
// fall of ‖V‖∞. The reference is the rest exact Newton steps (the factorisation, to 1e-12 N)
// reach from the loose state: the dome's slack corners hold nodes with almost no stiffness, so
// rests at 1e-9 N lie micrometres apart, and only the nearest is the one the estimate speaks of.
// Checked on the 101 × 101 dome at 1e-5 and 1e-6 N and on the 81 × 81 one at 1e-5 N. (On the
// 81 × 81 dome at 1e-6 N the estimate depends on the path: 1.25 × the distance in this version,
// 0.23 × in a build that summed the coarse matrices otherwise, its exact steps crossing the
// kinks of springs at the edge of slack; docs/speed.md, "Multigrid instead of the factorisation".)
TEST(PositionError, MultigridNewtonOnTheDomeIsWithinAFactorOfThreeOfTheMeasuredDistance) {
  for (const auto& [divisions, es] : {std::pair{100, std::vector<double>{1e-5, 1e-6}}, std::pair{80, std::vector<double>{1e-5}}}) {
    const DomeRuns dome(divisions, "multigrid");
    for (const double e : es) {
      Summary s;
      const SolverState loose = dome.solve_to(e, 0.0, &s);
      EXPECT_EQ(s.converged_on, StopCriterion::force);
      const double measured = largest_distance(loose, dome.exact_rest_from(loose));
      std::printf("dome at %d x %d divisions, e = %g N: estimate %.3g m, measured %.3g m\n", divisions, divisions, e,
                  s.position_error_m, measured);
      EXPECT_TRUE(s.position_error_m >= measured / 3 && s.position_error_m <= 3 * measured)
          << divisions << " divisions, e = " << e << " N: estimate " << s.position_error_m << " m, measured "
          << measured << " m";
    }
  }
  const DomeRuns dome(80, "multigrid");
  Summary s;
  const SolverState tight_reference = dome.solve_to(1e-300, 1e-9, &s);
  const SolverState stopped = dome.solve_to(1e-300, 1e-5, &s);
  EXPECT_EQ(s.converged_on, StopCriterion::position);
  EXPECT_LE(largest_distance(stopped, tight_reference), 3 * 1e-5);
}

TEST(PositionError, NegativeDistanceToleranceIsRefused) {
  NewtonOptions n;
  n.tolerance_m = -1e-3;
  std::string field;
  EXPECT_NE(n.invalid_reason(&field), "");
  EXPECT_EQ(field, "tolerance_m");
  RelaxOptions r;
  r.tolerance_m = std::nan("");
  EXPECT_NE(r.invalid_reason(&field), "");
  EXPECT_EQ(field, "tolerance_m");
  DynamicOptions d;
  d.tolerance_m = INFINITY;
  EXPECT_NE(d.invalid_reason(&field), "");
  EXPECT_EQ(field, "tolerance_m");
}

}  // namespace
}  // namespace fabform::position_error_test
