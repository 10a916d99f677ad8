// An interrupt stops every solver at the end of an iteration; resumed from its checkpoint the run
// ends where the uninterrupted one does, bit for bit. A NaN or Inf in the state stops it as a
// numerical failure naming the iteration and the node.
#include "fabform/solver/interrupt.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fabform/output/checkpoint.hpp"
#include "fabform/solver/solve.hpp"
#include "support/fabric_over_sphere.hpp"
#include "support/temp_dir.hpp"

namespace fabform::interrupt_test {
namespace {

SolverSpec spec_for(const std::string& solver) {
  SolverSpec spec;
  spec.name = solver;
  spec.relax.tolerance_N = spec.newton.tolerance_N = spec.dynamic.tolerance_N = 1e-6;
  return spec;
}

// Stops the run after `iteration` the way a signal would.
IterationObserver interrupt_after(int iteration) {
  return [iteration](const IterationRecord& r) {
    if (r.iteration == iteration) request_interrupt(2);
  };
}

class Interrupt : public ::testing::TestWithParam<const char*> {
 protected:
  void TearDown() override { clear_interrupt(); }
  const Model model = test::fabric_over_sphere(0.02);
  const SolverSpec spec = spec_for(GetParam());
};

TEST_P(Interrupt, StopsAtTheEndOfTheIterationAndResumesBitForBit) {
  SolverState whole = SolverState::at_start(model);
  const Summary uninterrupted = solve(model, whole, spec);
  ASSERT_TRUE(uninterrupted.converged()) << uninterrupted.message;
  const int stop_at = uninterrupted.iterations / 2;
  ASSERT_GT(stop_at, 0);

  SolverState part = SolverState::at_start(model);
  const Summary interrupted = solve(model, part, spec, interrupt_after(stop_at));
  EXPECT_EQ(interrupted.termination, Termination::interrupted);
  EXPECT_EQ(interrupted.iterations, stop_at);
  EXPECT_NE(interrupted.message.find("interrupted by signal 2"), std::string::npos) << interrupted.message;
  clear_interrupt();

  // Through the checkpoint file, as `fabform run --resume` does.
  test::TempDir dir;
  const std::string path = dir.write("checkpoint.bin", checkpoint_bytes(part, interrupted));
  Checkpoint c = read_checkpoint(path, model.node_count(), static_cast<int>(model.bodies.size()));
  const Summary resumed = solve(model, c.state, spec, {}, std::move(c.summary));
  ASSERT_TRUE(resumed.converged()) << resumed.message;
  EXPECT_EQ(resumed.iterations, uninterrupted.iterations);
  ASSERT_EQ(resumed.history.size(), uninterrupted.history.size());
  for (std::size_t i = 0; i < resumed.history.size(); ++i) {
    EXPECT_EQ(resumed.history[i].iteration, uninterrupted.history[i].iteration);
    EXPECT_EQ(resumed.history[i].residual_N, uninterrupted.history[i].residual_N) << "iteration " << i;
  }
  EXPECT_EQ(test::max_distance(c.state.x, whole.x), 0.0);
  EXPECT_GE(resumed.seconds, interrupted.seconds);
}

TEST_P(Interrupt, ARequestBeforeTheRunStopsItAtTheStart) {
  request_interrupt(15);
  SolverState state = SolverState::at_start(model);
  const Summary s = solve(model, state, spec);
  EXPECT_EQ(s.termination, Termination::interrupted);
  EXPECT_EQ(s.iterations, 0);
  EXPECT_EQ(test::max_distance(state.x, model.start), 0.0);
}

// A node's position turns NaN (or Inf) after iteration 2: the run stops in iteration 3 and names
// that node, whichever neighbours its value spread to.
TEST_P(Interrupt, NonFinitePositionIsANumericalFailureNamingNodeAndIteration) {
  const int broken = model.fabric.node(7, 9);
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    SolverState state = SolverState::at_start(model);
    const Summary s = solve(model, state, spec, [&](const IterationRecord& r) {
      if (r.iteration == 2) state.x[static_cast<std::size_t>(broken)].z() = bad;
    });
    EXPECT_EQ(s.termination, Termination::numerical_failure) << s.message;
    EXPECT_EQ(s.iterations, 3);
    EXPECT_EQ(s.worst_node, broken);
    EXPECT_NE(s.message.find("node " + std::to_string(broken) + " in iteration 3"), std::string::npos)
        << s.message;
  }
}

TEST(BeginSummary, RefusesAnotherSolversRun) {
  Summary relaxed;
  relaxed.solver = "relax";
  EXPECT_THROW(begin_summary("newton", 1e-6, relaxed), std::invalid_argument);
  const Summary fresh = begin_summary("newton", 1e-6);
  EXPECT_EQ(fresh.iterations, 0);
  EXPECT_EQ(fresh.solver, "newton");
}

INSTANTIATE_TEST_SUITE_P(EverySolver, Interrupt, ::testing::Values("relax", "dynamic", "newton"));

}  // namespace
}  // namespace fabform::interrupt_test
