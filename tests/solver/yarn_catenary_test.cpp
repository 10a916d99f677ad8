// Seed 000's yarn under gravity, held at both ends: a chain of masses whose springs are stiff
// enough to be all but inextensible must hang in the catenary y = a·cosh(x/a), with
// 2a·sinh(D/2a) = L for a span D and a length L. The yarn is a strip one division wide, its
// warp springs the yarn; the discrete chain approaches the curve as h², so its sag is checked
// against the catenary's and its error must fall about fourfold when the divisions double
// (Newton, which gets there in milliseconds; relax and dynamic need minutes on so stiff a yarn).
#include <gtest/gtest.h>

#include <memory>

#include <cmath>

#include "fabform/model/gravity.hpp"
#include "fabform/solver/solve.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::yarn_catenary_test {
namespace {

constexpr double kLength_m = 0.1;
constexpr double kSpan_m = 0.08;
constexpr double kWidth_m = 0.002;
constexpr double kDensity_kg_m2 = 0.2;
// Tension per width at the ends is ~ρ·g·L/2 / sin(slope) ≈ 0.12 N/m, so strain ~1e-5: the sag
// it adds is ~1e-5 of the sag, below what the test asks of the discretisation.
constexpr double kStiffness_N_m = 1e4;

// a with 2a·sinh(D/2a) = L, by bisection: the left side falls from ∞ to D as a grows.
double catenary_parameter() {
  double lo = 1e-4, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (2 * a * std::sinh(kSpan_m / (2 * a)) > kLength_m ? lo : hi) = a;
  }
  return 0.5 * (lo + hi);
}

double catenary_sag() {
  const double a = catenary_parameter();
  return a * (std::cosh(kSpan_m / (2 * a)) - 1.0);
}

// The yarn starts slack along a parabola below the line between its ends, both end pairs held.
Model yarn(int divisions) {
  Fabric grid({kLength_m, kWidth_m, divisions, 1});
  std::vector<AxisMask> locks(static_cast<std::size_t>(grid.node_count()), 0);
  std::vector<Eigen::Vector3d> start(static_cast<std::size_t>(grid.node_count()));
  for (int k = 0; k < grid.node_count(); ++k) {
    const double t = static_cast<double>(grid.i_of(k)) / divisions;
    start[static_cast<std::size_t>(k)] = {kSpan_m * t, grid.rest_position(k).y(), -0.02 * 4 * t * (1 - t)};
    if (grid.i_of(k) == 0 || grid.i_of(k) == divisions) locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
  }
  Model model{grid, test::linear_table(kStiffness_N_m), test::linear_table(kStiffness_N_m), locks, {}, start};
  model.terms.push_back(std::make_shared<Gravity>(grid, kDensity_kg_m2, kStandardGravity_m_s2));
  return model;
}

// The depth of the yarn's middle below its ends, at rest.
double resting_sag(int divisions) {
  const Model model = yarn(divisions);
  SolverSpec spec;
  spec.name = "newton";
  spec.newton.tolerance_N = 1e-11;
  SolverState state = SolverState::at_start(model);
  const Summary summary = solve(model, state, spec);
  EXPECT_TRUE(summary.converged()) << "N=" << divisions << ": " << summary.message;
  return -state.x[static_cast<std::size_t>(model.fabric.node(divisions / 2, 0))].z();
}

TEST(YarnCatenary, SagApproachesTheCatenaryAsTheSquareOfTheSpacing) {
  const double sag = catenary_sag();  // 2.65 cm
  ASSERT_GT(sag, 0.02);
  const double coarse = std::abs(resting_sag(20) - sag) / sag;
  const double fine = std::abs(resting_sag(40) - sag) / sag;
  EXPECT_LT(fine, 1e-3) << "relative sag error at N = 40";
  // h² convergence: 4× for each halving; 3× leaves room for the elastic stretch.
  EXPECT_GT(coarse / fine, 3.0) << "N = 20: " << coarse << ", N = 40: " << fine;
}

// Seed 000's point: a soft yarn stretches far beyond what yarn can (its rest here has springs
// over 15 % long), and Provot's limit keeps every spring within 1.1 × its rest length. dynamic
// without the limit reaches Newton's rest; with it, no spring is ever left beyond the limit.
double longest_strain(const Model& model, const SolverState& state) {
  double longest = 0.0;
  for (const Spring& s : model.fabric.springs())
    longest = std::max(longest, (state.x[static_cast<std::size_t>(s.b)] - state.x[static_cast<std::size_t>(s.a)]).norm() /
                                        s.rest_length - 1.0);
  return longest;
}

// Seed 000's own setting: the yarn held at its middle only, starting straight and level.
Model yarn_pinned_at_its_middle(int divisions, double stiffness_N_m) {
  Model model = yarn(divisions);
  model.warp = model.weft = test::linear_table(stiffness_N_m);
  for (int k = 0; k < model.node_count(); ++k) {
    model.start[static_cast<std::size_t>(k)] = model.fabric.rest_position(k);
    model.locks[static_cast<std::size_t>(k)] = model.fabric.i_of(k) == divisions / 2 ? kLockX | kLockY | kLockZ : 0;
  }
  return model;
}

TEST(YarnProvot, StretchLimitHoldsASoftYarnWithinTenPercent) {
  const Model model = yarn_pinned_at_its_middle(20, 0.5);
  SolverSpec spec;
  spec.newton.tolerance_N = spec.dynamic.tolerance_N = 1e-9;
  spec.dynamic.max_iterations = 200000;
  spec.name = "newton";
  SolverState newton = SolverState::at_start(model);
  ASSERT_TRUE(solve(model, newton, spec).converged());
  EXPECT_GT(longest_strain(model, newton), 0.15);

  spec.name = "dynamic";
  SolverState free_fall = SolverState::at_start(model);
  const Summary unlimited = solve(model, free_fall, spec);
  ASSERT_TRUE(unlimited.converged()) << unlimited.message;
  // e = 1e-9 N on springs of w·k/h = 0.1 N/m leaves lengths within ~1e-8 m, 2e-6 of h, each.
  EXPECT_NEAR(longest_strain(model, free_fall), longest_strain(model, newton), 1e-4);

  spec.dynamic.stretch_limit = 0.1;
  SolverState limited = SolverState::at_start(model);
  const Summary summary = solve(model, limited, spec);
  EXPECT_FALSE(summary.converged()) << "no rest has every spring within the limit";
  EXPECT_LE(longest_strain(model, limited), 0.1 + 1e-9);
}

}  // namespace
}  // namespace fabform::yarn_catenary_test
