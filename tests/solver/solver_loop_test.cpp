// The loop every solver runs, with steps made up for the test: a residual that falls by a factor
// each iteration stands for a solver. It records each state, stops where record_iteration says,
// goes on from a resumed run, ends a stalled run where it stands, and lets a step end the run on
// its distance from the rest; relax's and dynamic's steps estimate it from their last move.
#include "fabform/solver/solver_loop.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fabform/solver/interrupt.hpp"

namespace fabform::solver_loop_test {
namespace {

const auto kNow = [] { return std::chrono::steady_clock::now(); };

// A run whose ‖V‖∞ starts at 1 N and is divided by `factor` at each step.
struct FallingResidual {
  double residual_N = 1.0;
  double factor = 2.0;
  int final_estimates = 0;  // how often the loop asked for the final state's distance

  SolverSteps steps() {
    SolverSteps s;
    s.step = [this](Summary&) {
      residual_N /= factor;
      return StepOutcome::moved;
    };
    s.measure = [this] { return StateResidual{residual_N, 3, 7}; };
    s.final_position_error = [this](const Summary&) {
      ++final_estimates;
      return 0.25;
    };
    return s;
  }
};

StopSettings stop(double tolerance_N, int max_iterations, double tolerance_m = 0.0) {
  return {tolerance_N, tolerance_m, max_iterations};
}

TEST(SolverLoop, RecordsEachStateUntilTheResidualIsWithinE) {
  FallingResidual run;
  std::vector<int> observed;
  const Summary s = run_solver_loop("relax", stop(0.1, 100), run.steps(),
                                    [&](const IterationRecord& r) { observed.push_back(r.iteration); }, {}, kNow());
  EXPECT_EQ(s.solver, "relax");
  EXPECT_TRUE(s.converged());
  EXPECT_EQ(s.converged_on, StopCriterion::force);
  EXPECT_EQ(s.iterations, 4);  // 1/16 N ≤ 0.1 N
  EXPECT_EQ(s.residual_N, 1.0 / 16.0);
  EXPECT_EQ(s.worst_node, 3);
  ASSERT_EQ(s.history.size(), 5u);  // iteration 0, the start, and four steps
  EXPECT_EQ(s.history.back().contact_nodes, 7);
  EXPECT_EQ(observed, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(run.final_estimates, 1);
  EXPECT_EQ(s.position_error_m, 0.25);
  EXPECT_GE(s.seconds, s.history.back().seconds);
  EXPECT_EQ(s.message, stop_message(s));
}

TEST(SolverLoop, StopsAtTheIterationCap) {
  FallingResidual run;
  const Summary s = run_solver_loop("newton", stop(1e-9, 3), run.steps(), {}, {}, kNow());
  EXPECT_EQ(s.termination, Termination::not_converged);
  EXPECT_EQ(s.iterations, 3);
  EXPECT_EQ(run.final_estimates, 1);
  EXPECT_NE(s.message.find("iteration cap 3 reached"), std::string::npos) << s.message;
}

TEST(SolverLoop, AnInterruptStopsItAfterTheIteration) {
  FallingResidual run;
  const Summary s = run_solver_loop("dynamic", stop(1e-9, 100), run.steps(), [](const IterationRecord& r) {
    if (r.iteration == 2) request_interrupt(15);
  }, {}, kNow());
  clear_interrupt();
  EXPECT_EQ(s.termination, Termination::interrupted);
  EXPECT_EQ(s.iterations, 2);
  EXPECT_EQ(run.final_estimates, 0) << "an interrupted run is not estimated";
}

TEST(SolverLoop, AResumedRunGoesOnFromItsIterationsAndSeconds) {
  FallingResidual run;
  run.residual_N = 0.5;
  Summary resumed = begin_summary("relax", 0.1);
  resumed.history = {{0, 1.0, 0.0, 7}, {1, 0.5, 100.0, 7}};
  resumed.iterations = 1;
  resumed.seconds = 100.0;
  const Summary s = run_solver_loop("relax", stop(0.1, 100), run.steps(), {}, resumed, kNow());
  EXPECT_EQ(s.iterations, 4);
  ASSERT_EQ(s.history.size(), 5u) << "the state resumed from is measured again, in its own record";
  EXPECT_EQ(s.history[1].iteration, 1);
  EXPECT_GE(s.history[1].seconds, 100.0);
  EXPECT_GE(s.seconds, 100.0);
  EXPECT_THROW(run_solver_loop("newton", stop(0.1, 100), run.steps(), {}, resumed, kNow()), std::invalid_argument);
}

TEST(SolverLoop, AStalledStepEndsTheRunWhereItStands) {
  FallingResidual run;
  SolverSteps steps = run.steps();
  steps.step = [](Summary&) { return StepOutcome::stalled; };
  steps.stall_message = [](const Summary& s) { return "stalled after " + std::to_string(s.iterations); };
  const Summary s = run_solver_loop("newton", stop(0.1, 100), steps, {}, {}, kNow());
  EXPECT_EQ(s.termination, Termination::not_converged);
  EXPECT_EQ(s.message, "stalled after 0");
  EXPECT_EQ(s.history.size(), 1u) << "the unchanged state is not recorded again";
  EXPECT_EQ(run.final_estimates, 0);
}

TEST(SolverLoop, AStallAtABrokenStateIsANumericalFailure) {
  FallingResidual run;
  SolverSteps steps = run.steps();
  steps.step = [&](Summary&) {
    run.residual_N = std::numeric_limits<double>::quiet_NaN();
    return StepOutcome::stalled;
  };
  const Summary s = run_solver_loop("newton", stop(0.1, 100), steps, {}, {}, kNow());
  EXPECT_EQ(s.termination, Termination::numerical_failure);
  EXPECT_EQ(s.iterations, 1);
  EXPECT_NE(s.message.find("NaN or Inf at node 3"), std::string::npos) << s.message;
}

TEST(SolverLoop, AStepEndsTheRunOnItsDistanceFromTheRest) {
  FallingResidual run;
  SolverSteps steps = run.steps();
  steps.step = [](Summary& s) {
    return record_position_error(s, 1e-4) ? StepOutcome::stopped : StepOutcome::moved;
  };
  const Summary s = run_solver_loop("newton", stop(1e-9, 100, 1e-3), steps, {}, {}, kNow());
  EXPECT_TRUE(s.converged());
  EXPECT_EQ(s.converged_on, StopCriterion::position);
  EXPECT_EQ(s.iterations, 0);
  EXPECT_EQ(s.position_error_m, 1e-4);
  EXPECT_EQ(run.final_estimates, 0) << "the estimate that stopped it stands";
}

// One node moving toward 0 by half its distance each step, its ‖V‖∞ halving with it: the moves
// still to come sum to the last move, Δ·ρ/(1 − ρ) with ρ = 1/2.
struct HalvingNode {
  SolverState state;
  double residual_N = 1.0;

  HalvingNode() { state.x = {Eigen::Vector3d(1.0, 0.0, 0.0)}; }
  SolverSteps steps(double tolerance_m) {
    return rate_estimated_steps(state, tolerance_m, [this] { state.x[0] /= 2.0, residual_N /= 2.0; },
                                [this] { return StateResidual{residual_N, 0, 0}; });
  }
};

TEST(RateEstimatedSteps, EstimateTheDistanceFromTheLastMove) {
  HalvingNode node;
  const Summary s = run_solver_loop("relax", stop(1.0 / 64.0, 100), node.steps(0.0), {}, {}, kNow());
  EXPECT_EQ(s.iterations, 6);
  EXPECT_NEAR(s.position_error_m, 1.0 / 64.0, 1e-15);
  EXPECT_DOUBLE_EQ(node.state.x[0].x(), 1.0 / 64.0);
}

TEST(RateEstimatedSteps, StopTheRunWithinTolerance_m) {
  HalvingNode node;
  const Summary s = run_solver_loop("dynamic", stop(1e-9, 100, 0.01), node.steps(0.01), {}, {}, kNow());
  EXPECT_EQ(s.converged_on, StopCriterion::position);
  EXPECT_EQ(s.iterations, 7);  // the first estimate within 1 cm: 1/128 m after the seventh move
  EXPECT_NEAR(s.position_error_m, 1.0 / 128.0, 1e-15);
}

TEST(RateEstimatedSteps, HaveNoEstimateBeforeAMove) {
  HalvingNode node;
  const Summary s = run_solver_loop("relax", stop(2.0, 100), node.steps(0.0), {}, {}, kNow());
  EXPECT_EQ(s.iterations, 0);
  EXPECT_TRUE(std::isnan(s.position_error_m));
}

}  // namespace
}  // namespace fabform::solver_loop_test
