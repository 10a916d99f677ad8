// The seed 003 relaxation on small problems with known answers.
#include "fabform/solver/relax.hpp"

#include <gtest/gtest.h>

#include <memory>

#include <cmath>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/gravity.hpp"
#include "support/clamped_fabric.hpp"
#include "support/rotated_fabric.hpp"
#include "support/shapes.hpp"

namespace fabform::relax_test {
namespace {

using test::clamped_fabric;
using test::lift_interior;

// Relaxes from the model's start to `tolerance_N`, which it must reach; returns the final
// state's equilibrium recomputed from positions alone.
EquilibriumReport relax_to(const Model& model, double tolerance_N, SolverState* state) {
  *state = SolverState::at_start(model);
  RelaxOptions options;
  options.tolerance_N = tolerance_N;
  const Summary summary = relax(model, *state, options);
  EXPECT_EQ(summary.termination, Termination::converged) << summary.message;
  const EquilibriumReport check = measure_equilibrium(model, state->x, 1e-8);
  EXPECT_LE(check.max_residual_N, tolerance_N);
  return check;
}

TEST(RelaxOptions, RejectsBadValues) {
  RelaxOptions o;
  EXPECT_EQ(o.invalid_reason(), "");
  o.C = 1.0;
  EXPECT_NE(o.invalid_reason(), "");
  o = RelaxOptions{};
  o.tolerance_N = std::nan("");
  EXPECT_NE(o.invalid_reason(), "");
  o = RelaxOptions{};
  o.max_iterations = -1;
  EXPECT_NE(o.invalid_reason(), "");
  // C barely above 1 would need billions of divisions per node: refused, not a hang.
  o = RelaxOptions{};
  o.C = 1.0000000001;
  std::string field;
  EXPECT_NE(o.invalid_reason(&field), "");
  EXPECT_EQ(field, "C");
  o.C = 1e308;
  EXPECT_NE(o.invalid_reason(), "");
}

TEST(Relax, RefusesInvalidOptions) {
  Model model = clamped_fabric(2);
  SolverState state = SolverState::at_start(model);
  RelaxOptions options;
  options.C = 1.0;
  EXPECT_THROW(relax(model, state, options), std::invalid_argument);
}

// With no body, a pre-stretched clamped fabric lifted in the middle relaxes back to flat: every
// node returns to z = 0 and the residual recomputed from positions meets the tolerance.
TEST(Relax, LiftedFabricRelaxesToFlatWithoutBody) {
  Model model = clamped_fabric(10, 0.05);
  lift_interior(model, 0.01);
  SolverState state;
  relax_to(model, 1e-8, &state);
  // The out-of-plane stiffness of a node is about 4 T w / l = 4 · 25 N/m · 1 cm / 1 cm = 100 N/m,
  // so a residual of 1e-8 N leaves heights within ~1e-10 m; 1e-8 m is a safe bound.
  for (const auto& x : state.x) EXPECT_NEAR(x.z(), 0.0, 1e-8);
}

// A fabric laid out at rest, held at its corners, starts to fall under its weight in the first
// sweep. Its lengths differ from the rest lengths by rounding (~1e-17 m); a step Σ|d|/C taken
// from that would move no node for ever.
TEST(Relax, FabricLaidOutAtRestFallsUnderItsWeight) {
  Model model = test::rotated_fabric_at_rest(8);
  model.terms.push_back(std::make_shared<Gravity>(model.fabric, 0.2, kStandardGravity_m_s2));
  SolverState state = SolverState::at_start(model);
  RelaxOptions options;
  options.tolerance_N = 1e-8;  // below a node's weight, ~3e-4 N
  options.max_iterations = 1;
  const Summary summary = relax(model, state, options);
  ASSERT_EQ(summary.iterations, 1);
  const int centre = 40;
  const double spacing = 0.1 / 8;
  EXPECT_LT(state.x[centre].z(), model.start[centre].z() - 1e-3 * spacing);
}

// A pre-stretched square membrane over a sphere rises onto it: nodes touch, none enters it,
// and the residual recomputed independently meets the tolerance.
TEST(Relax, PrestretchedFabricOverSphereRestsOnIt) {
  Model model = clamped_fabric(20, 0.1);
  lift_interior(model, 0.02);  // clear of the sphere, whose top is at z = 0.01
  model.bodies.emplace_back("sphere", test::uv_sphere({0.05, 0.05, -0.02}, 0.03, 40, 80));
  SolverState state;
  const EquilibriumReport check = relax_to(model, 1e-6, &state);
  EXPECT_GT(check.contact_nodes, 10);
  // Contact is resolved on the tessellated sphere; 1e-9 m is far below its facets' size.
  EXPECT_LE(check.max_penetration_m, 1e-9);
  // The apex of the sphere sits 1 cm above the perimeter plane: the fabric's centre is on it.
  const Eigen::Vector3d centre = state.x[static_cast<std::size_t>(model.fabric.node(10, 10))];
  EXPECT_NEAR(centre.z(), 0.01, 1e-4);
}

// A locked node in contact keeps its locked coordinates: it is not projected onto the surface
// along them (seed 003 §3.2.3 with §3.2.2).
TEST(Relax, LockedNodesInContactKeepTheirLockedCoordinates) {
  Model model = clamped_fabric(20, 0.1);
  lift_interior(model, 0.02);
  model.bodies.emplace_back("sphere", test::uv_sphere({0.05, 0.05, -0.02}, 0.03, 40, 80));
  for (int j = 1; j < 20; ++j) model.locks[static_cast<std::size_t>(model.fabric.node(8, j))] = kLockX;
  SolverState state;
  const EquilibriumReport check = relax_to(model, 1e-6, &state);
  EXPECT_GT(check.contact_nodes, 10);
  EXPECT_LE(check.max_penetration_m, 1e-9);
  for (int j = 1; j < 20; ++j) {
    const auto k = static_cast<std::size_t>(model.fabric.node(8, j));
    EXPECT_EQ(state.x[k].x(), model.start[k].x()) << "node (8, " << j << ")";
  }
}

// Seed 003, §3.2.3: a node locked on an axis never moves along it.
TEST(Relax, LockedAxesDoNotMove) {
  Model model = clamped_fabric(8, 0.05);
  for (int k = 0; k < model.node_count(); ++k) {
    auto& x = model.start[static_cast<std::size_t>(k)];
    if (!model.fabric.on_perimeter(k)) x += Eigen::Vector3d(0.003, -0.002, 0.01);
  }
  const int locked_z = model.fabric.node(4, 4), locked_xy = model.fabric.node(2, 5);
  model.locks[static_cast<std::size_t>(locked_z)] = kLockZ;
  model.locks[static_cast<std::size_t>(locked_xy)] = kLockX | kLockY;
  SolverState state = SolverState::at_start(model);
  RelaxOptions options;
  options.tolerance_N = 1e-7;
  const Summary summary = relax(model, state, options);
  ASSERT_TRUE(summary.converged()) << summary.message;
  EXPECT_EQ(state.x[static_cast<std::size_t>(locked_z)].z(),
            model.start[static_cast<std::size_t>(locked_z)].z());
  EXPECT_EQ(state.x[static_cast<std::size_t>(locked_xy)].head<2>(),
            model.start[static_cast<std::size_t>(locked_xy)].head<2>());
  EXPECT_NE(state.x[static_cast<std::size_t>(locked_z)].head<2>(),
            model.start[static_cast<std::size_t>(locked_z)].head<2>());
  for (int k = 0; k < model.node_count(); ++k) {
    if (model.fabric.on_perimeter(k)) {
      EXPECT_EQ(state.x[static_cast<std::size_t>(k)], model.start[static_cast<std::size_t>(k)]);
    }
  }
}

TEST(Relax, StopsAtItsCapWithAHistory) {
  Model model = clamped_fabric(10, 0.05);
  lift_interior(model, 0.02);
  SolverState state = SolverState::at_start(model);
  RelaxOptions options;
  options.tolerance_N = 1e-12;
  options.max_iterations = 5;
  int observed = 0;
  const Summary summary = relax(model, state, options, [&](const IterationRecord&) { ++observed; });
  EXPECT_EQ(summary.termination, Termination::not_converged);
  EXPECT_EQ(to_string(summary.termination), "not converged");
  EXPECT_EQ(summary.iterations, 5);
  ASSERT_EQ(summary.history.size(), 6u);  // the start and five sweeps
  EXPECT_EQ(observed, 6);
  EXPECT_LT(summary.history.back().residual_N, summary.history.front().residual_N);
  for (std::size_t i = 1; i < summary.history.size(); ++i)
    EXPECT_GE(summary.history[i].seconds, summary.history[i - 1].seconds);
}

TEST(Relax, AlreadyInEquilibriumStopsAtIterationZero) {
  Model model = clamped_fabric(4);
  SolverState state = SolverState::at_start(model);
  const Summary summary = relax(model, state, RelaxOptions{});
  EXPECT_TRUE(summary.converged());
  EXPECT_EQ(summary.iterations, 0);
  EXPECT_LE(summary.residual_N, 1e-12);  // rounding of forces of about 1 N
}

TEST(Relax, NonFiniteStateIsANumericalFailure) {
  Model model = clamped_fabric(4);
  model.start[static_cast<std::size_t>(model.fabric.node(2, 2))].z() = std::nan("");
  SolverState state = SolverState::at_start(model);
  const Summary summary = relax(model, state, RelaxOptions{});
  EXPECT_EQ(summary.termination, Termination::numerical_failure);
  EXPECT_EQ(to_string(summary.termination), "numerical failure");
}

// Every C > 1 relaxes; a C near 1 divides the step slowly but must still converge.
class RelaxC : public ::testing::TestWithParam<double> {};

TEST_P(RelaxC, Converges) {
  Model model = clamped_fabric(6, 0.05);
  lift_interior(model, 0.01);
  SolverState state = SolverState::at_start(model);
  RelaxOptions options;
  options.C = GetParam();
  options.tolerance_N = 1e-6;
  options.max_iterations = 200000;
  const Summary summary = relax(model, state, options);
  EXPECT_TRUE(summary.converged()) << "C = " << GetParam() << ": " << summary.message;
  EXPECT_LE(measure_equilibrium(model, state.x, 1e-9).max_residual_N, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(SeedConstant, RelaxC, ::testing::Values(1.01, 1.5, 2.0, 10.0, 100.0));

}  // namespace
}  // namespace fabform::relax_test
