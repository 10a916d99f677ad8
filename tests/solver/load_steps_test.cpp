// Load steps (load_steps.hpp) against a closed form: a strip held at both ends 20 cm apart and
// a cylinder (radius 2 cm, along y) pushed up into its middle in K steps. Without friction the
// strip rests on two straight tangents and the arc between them with one tension, so every
// spring's strain is L/L₀ − 1, L = 2√(d² − r²) + r(π − 2θ) (d the distance from an end to the
// axis, θ the tangent point's angle). Each step is reported, records carry their step, the
// bodies end where the path ends, and a run interrupted inside a step or between two and
// resumed from its checkpoint ends bit for bit where the whole run ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <vector>

#include "fabform/geometry/rigid_body.hpp"
#include "fabform/fabric/spring.hpp"
#include "fabform/output/checkpoint.hpp"
#include "fabform/output/run_monitor.hpp"
#include "fabform/solver/interrupt.hpp"
#include "fabform/solver/load_steps.hpp"
#include "support/clamped_fabric.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"

namespace fabform::load_steps_test {
namespace {

constexpr double kHalfSpan_m = 0.1;
constexpr double kRadius_m = 0.02;
constexpr double kTravel_m = 0.05;
constexpr double kAxisStart_m = -0.03;  // the cylinder's top starts 1 cm under the strip
constexpr int kSteps = 5;

Model punched_strip(double friction = 0.0) {
  Fabric strip({2.0 * kHalfSpan_m, 0.01, 100, 1});
  std::vector<AxisMask> locks(static_cast<std::size_t>(strip.node_count()), 0);
  std::vector<Eigen::Vector3d> start;
  for (int k = 0; k < strip.node_count(); ++k) {
    start.push_back(strip.rest_position(k) - Eigen::Vector3d(kHalfSpan_m, 0.0, 0.0));
    if (strip.i_of(k) == 0 || strip.i_of(k) == 100) locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
  }
  TriangleMesh cylinder = test::cylinder_along_y(kRadius_m, -0.05, 0.06, 1024);
  for (auto& v : cylinder.vertices) v.z() += kAxisStart_m;
  std::vector<RigidBody> bodies;
  bodies.emplace_back("punch", std::move(cylinder), friction);
  Model model{strip, test::linear_table(500.0), test::linear_table(500.0), locks, std::move(bodies), start};
  model.paths = {ToolPath{Eigen::Vector3d(0.0, 0.0, kTravel_m), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), kSteps}};
  return model;
}

SolverSpec newton_spec() {
  SolverSpec spec;
  spec.name = "newton";
  spec.newton.tolerance_N = 1e-9;
  return spec;
}

double tangents_and_arc_strain() {
  const double pi = std::acos(-1.0);
  const double height = kAxisStart_m + kTravel_m;  // the axis above the held ends
  const double d = std::hypot(kHalfSpan_m, height);
  const double tangent_angle = std::atan2(-height, kHalfSpan_m) + std::acos(kRadius_m / d);
  const double length = 2.0 * std::sqrt(d * d - kRadius_m * kRadius_m) + kRadius_m * (pi - 2.0 * tangent_angle);
  return length / (2.0 * kHalfSpan_m) - 1.0;
}

TEST(LoadSteps, APunchedStripTakesTheLengthOfItsTangentsAndArc) {
  Model model = punched_strip();
  SolverState state = SolverState::at_start(model);
  std::vector<int> finished;
  const Summary s = solve_in_steps(model, state, newton_spec(), {},
                                   [&](int step, const SolverState&, const Summary& of_step) {
                                     EXPECT_TRUE(of_step.converged()) << step;
                                     finished.push_back(step);
                                   });
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_EQ(finished, (std::vector<int>{1, 2, 3, 4, 5}));
  EXPECT_EQ(s.history.front().step, 1);
  EXPECT_EQ(s.history.back().step, kSteps);
  EXPECT_EQ(s.iterations, total_iterations(s.history));
  EXPECT_TRUE(model.bodies[0].pose().isApprox(model.paths[0].pose(kSteps), 0.0));
  // The discrete strip's chords over the arc (2 mm springs on a 2 cm radius) shorten it by
  // about 1e-5; the strain (7.9 %) is met within 2e-4.
  const double expected = tangents_and_arc_strain();
  ASSERT_GT(expected, 0.07);
  for (const Spring& spring : model.fabric.springs()) {
    if (spring.kind != SpringKind::warp) continue;
    EXPECT_NEAR(spring_strain(state.x[static_cast<std::size_t>(spring.a)], state.x[static_cast<std::size_t>(spring.b)],
                              spring.rest_length),
                expected, 2e-4);
  }
}

// Nodes resting on the cylinder ride up with it; none ends inside it by more than the rounding
// of carrying it (1e-9 of the body's size).
TEST(LoadSteps, NoNodeEndsInsideTheTravellingBody) {
  Model model = punched_strip(0.3);
  SolverState state = SolverState::at_start(model);
  ASSERT_TRUE(solve_in_steps(model, state, newton_spec(), {}, {}).converged());
  const double rounding = 1e-9 * model.bodies[0].box().diagonal();
  for (const Eigen::Vector3d& x : state.x) EXPECT_GE(model.bodies[0].closest(x).signed_distance, -rounding);
}

// The checkpoint holds every record's step: interrupted at `when`, written, read back and
// resumed with bodies placed afresh, the run ends where the uninterrupted one does.
void expect_resumed_run_ends_where_the_whole_ends(int step, int iteration) {
  Model whole = punched_strip(0.3);
  SolverState whole_state = SolverState::at_start(whole);
  ASSERT_TRUE(solve_in_steps(whole, whole_state, newton_spec(), {}, {}).converged());

  Model part = punched_strip(0.3);
  SolverState part_state = SolverState::at_start(part);
  const Summary stopped = solve_in_steps(part, part_state, newton_spec(), [&](const IterationRecord& r) {
    if (r.step == step && r.iteration == iteration) request_interrupt(SIGINT);
  }, {});
  clear_interrupt();
  ASSERT_EQ(stopped.termination, Termination::interrupted) << stopped.message;
  test::TempDir dir;
  const std::string file = dir.write("checkpoint.bin", checkpoint_bytes(part_state, stopped));
  Checkpoint taken_up = read_checkpoint(file, part.node_count(), 1);
  Model again = punched_strip(0.3);  // its body stands at its placement, as in a new process
  ASSERT_TRUE(solve_in_steps(again, taken_up.state, newton_spec(), {}, {}, taken_up.summary).converged());
  for (std::size_t k = 0; k < whole_state.x.size(); ++k) EXPECT_EQ(taken_up.state.x[k], whole_state.x[k]) << k;
}

TEST(LoadSteps, ResumedInsideAStepEndsBitForBitWhereTheWholeRunEnds) {
  expect_resumed_run_ends_where_the_whole_ends(3, 2);
}

// Interrupted as step 2 begins (after the carry, at its iteration 0).
TEST(LoadSteps, ResumedBetweenStepsEndsBitForBitWhereTheWholeRunEnds) {
  expect_resumed_run_ends_where_the_whole_ends(2, 0);
}

// Step 1 only brings the cylinder's top up to the strip; step 2 needs more than one iteration.
// Without cuts (max_step_cuts = 0) the step's own failure ends the run, as it did before cuts.
TEST(LoadSteps, AStepThatDoesNotConvergeEndsTheRunNamingIt) {
  Model model = punched_strip();
  SolverState state = SolverState::at_start(model);
  SolverSpec spec = newton_spec();
  spec.newton.max_iterations = 1;
  spec.max_step_cuts = 0;
  std::vector<int> finished;
  const Summary s = solve_in_steps(model, state, spec, {},
                                   [&](int step, const SolverState&, const Summary&) { finished.push_back(step); });
  EXPECT_EQ(s.termination, Termination::not_converged);
  EXPECT_EQ(finished, std::vector<int>{1});
  EXPECT_EQ(s.history.back().step, 2);
  EXPECT_EQ(s.message.rfind("load step 2 of 5: iteration cap 1 reached", 0), 0u) << s.message;
}

// A path's pose at a fractional progress (a cut step's): at a whole number it is pose(int) bit
// for bit, so that a run without cuts does what it did before them; half way through a step it
// has moved and turned half the step's way.
TEST(ToolPath, PoseAtAWholeProgressIsPoseAndHalfAStepIsTheMidpoint) {
  const ToolPath path{Eigen::Vector3d(0.01, -0.02, 0.05), Eigen::Vector3d(0.0, 0.0, 70.0),
                      Eigen::Vector3d(0.1, 0.2, 0.3), 7};
  for (int step = 0; step <= 7; ++step) {
    const Eigen::Isometry3d whole = path.pose(step);
    const Eigen::Isometry3d at = path.pose_at(static_cast<double>(step));
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(at.matrix()(r, c), whole.matrix()(r, c)) << step << " " << r << c;
  }
  const ToolPath push{Eigen::Vector3d(0.01, -0.02, 0.05), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 7};
  const ToolPath turn{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 70.0), Eigen::Vector3d::Zero(), 7};
  for (int step = 1; step <= 7; ++step) {
    const double half = step - 0.5;
    const Eigen::Vector3d midpoint = 0.5 * (push.translation_at(step - 1) + push.translation_at(step));
    EXPECT_TRUE(push.pose_at(half).translation().isApprox(midpoint, 1e-15)) << step;
    EXPECT_TRUE(push.pose_at(half).linear().isIdentity(0.0)) << step;
    const double angle_deg = Eigen::AngleAxisd(turn.pose_at(half).linear()).angle() * 180.0 / std::acos(-1.0);
    EXPECT_NEAR(angle_deg, 0.5 * (turn.rotation_deg_at(step - 1).z() + turn.rotation_deg_at(step).z()), 1e-12) << step;
    EXPECT_NEAR(angle_deg, 10.0 * half, 1e-12) << step;
  }
  // The pivot stays where it is at any progress.
  EXPECT_TRUE((path.pose_at(2.25) * path.pivot_m).isApprox(path.pivot_m + 2.25 / 7.0 * path.translation_m, 1e-15));
}

// A taut strip (held 2 % beyond its length) and the cylinder pushed 3 cm up into it from where
// its top touches it, in `steps` load steps. Found by experiment (newton to 1e-9 N): in 2 steps
// the steps take 17 and 35 iterations, in 4 steps 12, 12, 10 and 9, so with a cap of 14 each of
// the 2 steps fails whole and converges in halves, which are the 4 steps' steps.
Model taut_strip(int steps) {
  Fabric strip({2.0 * kHalfSpan_m, 0.01, 100, 1});
  std::vector<AxisMask> locks(static_cast<std::size_t>(strip.node_count()), 0);
  std::vector<Eigen::Vector3d> start;
  for (int k = 0; k < strip.node_count(); ++k) {
    Eigen::Vector3d x = strip.rest_position(k) - Eigen::Vector3d(kHalfSpan_m, 0.0, 0.0);
    x.x() *= 1.02;
    start.push_back(x);
    if (strip.i_of(k) == 0 || strip.i_of(k) == 100) locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
  }
  TriangleMesh cylinder = test::cylinder_along_y(kRadius_m, -0.05, 0.06, 1024);
  for (auto& v : cylinder.vertices) v.z() -= kRadius_m;
  std::vector<RigidBody> bodies;
  bodies.emplace_back("punch", std::move(cylinder), 0.0);
  Model model{strip, test::linear_table(500.0), test::linear_table(500.0), locks, std::move(bodies), start};
  model.paths = {ToolPath{Eigen::Vector3d(0.0, 0.0, 0.03), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), steps}};
  return model;
}

constexpr int kCutCap = 14;

SolverSpec capped_spec(int max_step_cuts) {
  SolverSpec spec = newton_spec();
  spec.newton.max_iterations = kCutCap;
  spec.max_step_cuts = max_step_cuts;
  return spec;
}

struct FinishedStep {
  int step;
  int iterations;
  StepCuts cuts;
};

// A step that fails whole is cut in half and converges: each of the 2 steps is cut once, its
// halves are the steps of the run in 4 steps, and the run ends bit for bit where that one ends.
// Each step's records keep its number and count on over its attempts (the failed whole step's
// cap, then each half's iterations).
TEST(LoadSteps, AStepThatFailsWholeConvergesInHalves) {
  Model quarters = taut_strip(4);
  SolverState quarters_state = SolverState::at_start(quarters);
  std::vector<int> quarter_iterations;
  const Summary in_four = solve_in_steps(quarters, quarters_state, capped_spec(0), {},
                                         [&](int, const SolverState&, const Summary& of_step) {
                                           quarter_iterations.push_back(of_step.iterations);
                                         });
  ASSERT_TRUE(in_four.converged()) << in_four.message;
  ASSERT_EQ(quarter_iterations.size(), 4u);

  Model model = taut_strip(2);
  SolverState state = SolverState::at_start(model);
  std::vector<FinishedStep> finished;
  const Summary s = solve_in_steps(model, state, capped_spec(4), {},
                                   [&](int step, const SolverState&, const Summary& of_step, const StepCuts& cuts) {
                                     EXPECT_TRUE(of_step.converged()) << step;
                                     finished.push_back({step, of_step.iterations, cuts});
                                   });
  ASSERT_TRUE(s.converged()) << s.message;
  ASSERT_EQ(finished.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(finished[k].step, k + 1);
    EXPECT_EQ(finished[k].cuts.cuts, 1) << k;
    EXPECT_EQ(finished[k].cuts.smallest_fraction, 0.5) << k;
    EXPECT_EQ(finished[k].iterations, kCutCap + quarter_iterations[2 * k] + quarter_iterations[2 * k + 1]) << k;
  }
  for (std::size_t i = 1; i < s.history.size(); ++i) {
    if (s.history[i].step == s.history[i - 1].step) {
      EXPECT_GT(s.history[i].iteration, s.history[i - 1].iteration) << i;
    }
  }
  EXPECT_EQ(s.history.front().step, 1);
  EXPECT_EQ(s.history.back().step, 2);
  EXPECT_EQ(s.iterations, total_iterations(s.history));
  EXPECT_EQ(s.iterations, finished[0].iterations + finished[1].iterations);
  EXPECT_TRUE(model.bodies[0].pose().isApprox(model.paths[0].pose(2), 0.0));
  for (std::size_t k = 0; k < state.x.size(); ++k) EXPECT_EQ(state.x[k], quarters_state.x[k]) << k;
}

// With max_step_cuts = 0 the same run ends where it ended before cuts: in its first step.
TEST(LoadSteps, WithoutCutsTheStepThatFailsWholeEndsTheRun) {
  Model model = taut_strip(2);
  SolverState state = SolverState::at_start(model);
  std::vector<int> finished;
  const Summary s = solve_in_steps(model, state, capped_spec(0), {},
                                   [&](int step, const SolverState&, const Summary&) { finished.push_back(step); });
  EXPECT_EQ(s.termination, Termination::not_converged);
  EXPECT_TRUE(finished.empty());
  EXPECT_EQ(s.history.back().step, 1);
  EXPECT_EQ(s.history.back().iteration, kCutCap);
  EXPECT_EQ(s.message.rfind("load step 1 of 2: iteration cap 14 reached", 0), 0u) << s.message;
  EXPECT_EQ(s.message.find("cut"), std::string::npos) << s.message;
}

// A part of the smallest size (here a half: max_step_cuts = 1) that fails ends the run; its
// message names the step and says its cuts were exhausted, and the cap it gives is one
// attempt's.
TEST(LoadSteps, ExhaustedCutsEndTheRunSayingSo) {
  Model model = taut_strip(2);
  SolverState state = SolverState::at_start(model);
  SolverSpec spec = capped_spec(1);
  spec.newton.max_iterations = 5;
  std::vector<int> finished;
  const Summary s = solve_in_steps(model, state, spec, {},
                                   [&](int step, const SolverState&, const Summary&) { finished.push_back(step); });
  EXPECT_EQ(s.termination, Termination::not_converged);
  EXPECT_FALSE(s.converged());
  EXPECT_TRUE(finished.empty());
  EXPECT_EQ(s.history.back().step, 1);
  EXPECT_EQ(s.message.rfind("load step 1 of 2: its cuts were exhausted (max_step_cuts = 1): the part of 1/2 of the "
                            "step from progress 0 to 0.5 did not converge either: iteration cap 5 reached",
                            0),
            0u)
      << s.message;
}

// Interrupted while a step is being cut, the run goes back to where the step began (its records
// dropped, the body where it stood); resumed from its checkpoint it cuts the step again and
// ends bit for bit where the uninterrupted run ends.
TEST(LoadSteps, InterruptedWhileCuttingResumesFromTheStepsStart) {
  Model whole = taut_strip(2);
  SolverState whole_state = SolverState::at_start(whole);
  ASSERT_TRUE(solve_in_steps(whole, whole_state, capped_spec(4), {}, {}).converged());

  Model part = taut_strip(2);
  SolverState part_state = SolverState::at_start(part);
  SolverState after_step_1;
  const Summary stopped = solve_in_steps(
      part, part_state, capped_spec(4),
      [&](const IterationRecord& r) {
        if (r.step == 2 && r.iteration == kCutCap + 3) request_interrupt(SIGINT);  // in step 2's first half
      },
      [&](int, const SolverState& s, const Summary&) { after_step_1 = s; });
  clear_interrupt();
  ASSERT_EQ(stopped.termination, Termination::interrupted) << stopped.message;
  EXPECT_NE(stopped.message.find("load step 2 was being cut"), std::string::npos) << stopped.message;
  EXPECT_EQ(stopped.history.back().step, 1);
  EXPECT_EQ(stopped.iterations, total_iterations(stopped.history));
  EXPECT_TRUE(part.bodies[0].pose().isApprox(part.paths[0].pose(1), 0.0));
  for (std::size_t k = 0; k < part_state.x.size(); ++k) ASSERT_EQ(part_state.x[k], after_step_1.x[k]) << k;

  test::TempDir dir;
  const std::string file = dir.write("checkpoint.bin", checkpoint_bytes(part_state, stopped));
  Checkpoint taken_up = read_checkpoint(file, part.node_count(), 1);
  Model again = taut_strip(2);
  std::vector<StepCuts> cuts;
  ASSERT_TRUE(solve_in_steps(again, taken_up.state, capped_spec(4), {},
                             [&](int, const SolverState&, const Summary&, const StepCuts& c) { cuts.push_back(c); },
                             taken_up.summary)
                  .converged());
  ASSERT_EQ(cuts.size(), 2u);  // step 1 finished again from its rest, uncut; step 2 cut again
  EXPECT_EQ(cuts[0].cuts, 0);
  EXPECT_EQ(cuts[1].cuts, 1);
  for (std::size_t k = 0; k < whole_state.x.size(); ++k) EXPECT_EQ(taken_up.state.x[k], whole_state.x[k]) << k;
}

// A checkpoint holds a state at a whole pose; inside a cut the bodies stand at a part of the
// step, so the monitor writes none there, however often it is asked to (every iteration here):
// the step's last checkpoint before its end is its whole attempt's.
TEST(LoadSteps, NoCheckpointIsWrittenInsideACut) {
  Model model = taut_strip(2);
  SolverState state = SolverState::at_start(model);
  std::vector<int> written;  // step 2's iterations checkpointed
  RunMonitor monitor(state, {}, CheckpointSpec{1, 0.0},
                     [&](const SolverState&, const Summary& so_far) {
                       if (so_far.history.back().step == 2) written.push_back(so_far.history.back().iteration);
                     },
                     nullptr);
  const Summary run =
      solve_in_steps(model, state, capped_spec(4), [&](const IterationRecord& r) { monitor.observe(r); }, {});
  ASSERT_TRUE(run.converged()) << run.message;
  ASSERT_GT(run.history.back().iteration, kCutCap);  // step 2 was cut
  ASSERT_FALSE(written.empty());
  EXPECT_LE(*std::max_element(written.begin(), written.end()), kCutCap);
}

}  // namespace
}  // namespace fabform::load_steps_test
