// Load steps (load_steps.hpp) against a closed form: a strip held at both ends 20 cm apart and
// a cylinder (radius 2 cm, along y) pushed up into its middle in K steps. Without friction the
// strip rests on two straight tangents and the arc between them with one tension, so every
// spring's strain is L/L₀ − 1, L = 2√(d² − r²) + r(π − 2θ) (d the distance from an end to the
// axis, θ the tangent point's angle). Each step is reported, records carry their step, the
// bodies end where the path ends, and a run interrupted inside a step or between two and
// resumed from its checkpoint ends bit for bit where the whole run ends.
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>

#include "fabform/geometry/rigid_body.hpp"
#include "fabform/fabric/spring.hpp"
#include "fabform/output/checkpoint.hpp"
#include "fabform/solver/interrupt.hpp"
#include "fabform/solver/load_steps.hpp"
#include "support/clamped_fabric.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"

namespace fabform {
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
TEST(LoadSteps, AStepThatDoesNotConvergeEndsTheRunNamingIt) {
  Model model = punched_strip();
  SolverState state = SolverState::at_start(model);
  SolverSpec spec = newton_spec();
  spec.newton.max_iterations = 1;
  std::vector<int> finished;
  const Summary s = solve_in_steps(model, state, spec, {},
                                   [&](int step, const SolverState&, const Summary&) { finished.push_back(step); });
  EXPECT_EQ(s.termination, Termination::not_converged);
  EXPECT_EQ(finished, std::vector<int>{1});
  EXPECT_EQ(s.history.back().step, 2);
  EXPECT_EQ(s.message.rfind("load step 2 of 5: iteration cap 1 reached", 0), 0u) << s.message;
}

}  // namespace
}  // namespace fabform
