// Every solver at the extremes an engineer can reach from a scene: a stiffness ratio of 10⁴
// between warp and weft, springs at thousands of percent strain, a near-vertical table segment,
// relax's C at 1.01 and 100, a tolerance of 1e-12, grids of 2 × 2 and 1000 × 1000 nodes, springs
// of zero length, nodes starting on the body's surface. Each run converges or stops with a named
// termination within its cap, and no position or residual it hands back is NaN.
#include <gtest/gtest.h>

#include <string>

#include "fabform/model/equilibrium.hpp"
#include "fabform/solver/solve.hpp"
#include "support/clamped_fabric.hpp"
#include "support/fabric_over_sphere.hpp"

namespace fabform::extremes_test {
namespace {

using test::clamped_fabric;
using test::fabric_over_sphere;
using test::lift_interior;
using test::linear_table;

struct Outcome {
  Summary summary;
  SolverState state;
  int cap = 0;
};

// Caps that end each solver's run in seconds on these small problems: relax sweeps, dynamic
// time steps, Newton steps.
int default_cap(const std::string& solver) {
  if (solver == "relax") return 20000;
  if (solver == "dynamic") return 200000;
  return 200;
}

Outcome run(const Model& model, const std::string& solver, double tolerance_N, int cap = -1,
        double C = 2.0) {
  SolverSpec spec;
  spec.name = solver;
  spec.relax.tolerance_N = spec.newton.tolerance_N = spec.dynamic.tolerance_N = tolerance_N;
  spec.relax.max_iterations = spec.newton.max_iterations = spec.dynamic.max_iterations =
      cap >= 0 ? cap : default_cap(solver);
  spec.relax.C = C;
  Outcome r{{}, SolverState::at_start(model), spec.relax.max_iterations};
  r.summary = solve(model, r.state, spec);
  return r;
}

// Named, within the cap, and nothing NaN: positions, the solver's residual, and the residual
// recomputed from the positions.
void expect_sane(const Model& model, const Outcome& r) {
  const Termination t = r.summary.termination;
  EXPECT_TRUE(t == Termination::converged || t == Termination::not_converged) << r.summary.message;
  EXPECT_FALSE(to_string(t).empty());
  EXPECT_LE(r.summary.iterations, r.cap);
  EXPECT_FALSE(r.summary.message.empty());
  for (const auto& x : r.state.x) ASSERT_TRUE(x.allFinite());
  EXPECT_FALSE(std::isnan(r.summary.residual_N));
  EXPECT_FALSE(std::isnan(measure_equilibrium(model, r.state.x, 1e-8).max_residual_N));
}

void expect_converged(const Model& model, const Outcome& r) {
  expect_sane(model, r);
  EXPECT_TRUE(r.summary.converged()) << r.summary.solver << ": " << r.summary.message;
  EXPECT_LE(measure_equilibrium(model, r.state.x, 1e-8).max_residual_N, r.summary.tolerance_N);
}

class Extremes : public ::testing::TestWithParam<std::string> {};

// Warp 100 times stiffer than the linear-500 fabric, weft 100 times softer.
TEST_P(Extremes, WarpToWeftStiffnessRatioOf1e4) {
  Model model = clamped_fabric(10, 0.05);
  model.warp = linear_table(5e4);
  model.weft = linear_table(5.0);
  lift_interior(model, 0.01);
  expect_converged(model, run(model, GetParam(), 1e-6));
}

// Every interior node 20 cm over a 10 cm fabric: springs at up to ~3900 % strain.
TEST_P(Extremes, HarshStartOver1000PercentStrain) {
  const Model model = fabric_over_sphere(0.2);
  expect_converged(model, run(model, GetParam(), 1e-6));
}

// A segment 1000 times steeper than the rest, 1e-6 of strain wide, that the rest crosses.
// dynamic's time step follows the steepest segment (√1000 ≈ 32 times shorter) while the fabric
// rests on the soft ones, so it is still far from rest at its cap: it must stop there, named.
TEST_P(Extremes, NearVerticalTableSegment) {
  Model model = clamped_fabric(10, 0.05);
  model.warp = model.weft = TensionTable({{0.0, 0.0}, {0.04, 20.0}, {0.040001, 20.5}, {1.0, 500.0}});
  lift_interior(model, 0.01);
  const Outcome r = run(model, GetParam(), 1e-6);
  if (GetParam() == "dynamic") expect_sane(model, r);
  else expect_converged(model, r);
}

// 1e-12 N is below what rounding lets most states reach: the run ends at its cap, or converges.
TEST_P(Extremes, ToleranceOf1e12StopsAtItsCap) {
  const Model model = fabric_over_sphere(0.02);
  const int cap = GetParam() == "newton" ? 30 : 300;
  const Outcome r = run(model, GetParam(), 1e-12, cap);
  expect_sane(model, r);
  if (!r.summary.converged()) {
    EXPECT_EQ(r.summary.termination, Termination::not_converged);
  }
}

// Four nodes, one corner held, the others pulled out to twice their distance.
TEST_P(Extremes, TwoByTwoGrid) {
  Model model = clamped_fabric(1);
  for (int k = 0; k < 4; ++k) {
    const auto i = static_cast<std::size_t>(k);
    model.locks[i] = k == 0 ? kLockX | kLockY | kLockZ : 0;
    model.start[i] = 2.0 * model.fabric.rest_position(k) + Eigen::Vector3d(0, 0, 0.01 * k);
  }
  expect_converged(model, run(model, GetParam(), 1e-9));
}

// One million nodes: each solver takes its first iterations (Newton's one step on three million
// unknowns, solved by multigrid as `auto` chooses from a million, is what takes the time: 37 s
// here) and stops at its cap with a named termination. (‖V‖∞ may rise in relax's first sweep: Gauss–Seidel moves the worst node's
// neighbours too.)
TEST_P(Extremes, ThousandByThousandGrid) {
  Model model = clamped_fabric(999, 0.05);
  lift_interior(model, 0.01);
  const int cap = GetParam() == "dynamic" ? 10 : 1;
  const Outcome r = run(model, GetParam(), 1e-6, cap);
  expect_sane(model, r);
  EXPECT_EQ(r.summary.termination, Termination::not_converged);
}

// Every interior node starts at the same point: the springs among them have zero length and
// no direction. They carry no force until the nodes part.
TEST_P(Extremes, ZeroLengthSprings) {
  Model model = clamped_fabric(6, 0.05);
  for (int k = 0; k < model.node_count(); ++k)
    if (!model.fabric.on_perimeter(k)) model.start[static_cast<std::size_t>(k)] = {0.05, 0.05, 0.01};
  expect_converged(model, run(model, GetParam(), 1e-6));
}

// The interior nodes above the sphere start on its surface: the closest point of the faceted
// mesh to where the lift put them.
TEST_P(Extremes, NodesStartingExactlyOnTheSurface) {
  Model model = fabric_over_sphere(0.02);
  int on_surface = 0;
  for (int k = 0; k < model.node_count(); ++k) {
    auto& x = model.start[static_cast<std::size_t>(k)];
    if (model.fabric.on_perimeter(k) || (x.head<2>() - Eigen::Vector2d(0.05, 0.05)).norm() > 0.02) continue;
    x = model.bodies.front().closest(x).point;
    ++on_surface;
  }
  ASSERT_GT(on_surface, 20);
  const Outcome r = run(model, GetParam(), 1e-8);
  expect_converged(model, r);
  EXPECT_LE(measure_equilibrium(model, r.state.x, 1e-8).max_penetration_m, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(EverySolver, Extremes, ::testing::Values("relax", "dynamic", "newton"),
                         [](const auto& case_info) { return case_info.param; });

// relax's C at the ends of what engineers use: barely above 1 (tiny first steps, shrinking
// slowly) and 100 (big first steps divided hard).
TEST(ExtremesRelax, StepDivisorC) {
  for (const double C : {1.01, 100.0}) {
    Model model = clamped_fabric(10, 0.05);
    lift_interior(model, 0.01);
    const Outcome r = run(model, "relax", 1e-6, 200000, C);
    expect_converged(model, r);
  }
}

}  // namespace
}  // namespace fabform::extremes_test
