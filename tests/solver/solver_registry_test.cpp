// The table of solvers: each row runs its own solver with its own options from the spec, and
// the spec's tolerances are read from the named solver's options and set in every solver's.
#include "fabform/solver/solver_registry.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "support/clamped_fabric.hpp"

namespace fabform::solver_registry_test {
namespace {

TEST(SolverRegistry, ListsTheSolversInTheirOrder) {
  std::vector<std::string> names;
  for (const SolverEntry& solver : solvers()) names.push_back(solver.name);
  EXPECT_EQ(names, (std::vector<std::string>{"relax", "dynamic", "newton"}));
}

TEST(SolverRegistry, FindsASolverByItsName) {
  EXPECT_EQ(find_solver("newton"), &solvers().back());
  EXPECT_EQ(find_solver("simplex"), nullptr);
  EXPECT_EQ(&solver_named("relax"), &solvers().front());
  EXPECT_THROW(solver_named("simplex"), std::invalid_argument);
}

TEST(SolverRegistry, EachRowRunsItsSolverWithItsOptions) {
  Model model = test::clamped_fabric(4, 0.01);
  test::lift_interior(model, 0.01);
  SolverSpec spec;
  spec.newton.max_iterations = 0;  // newton alone stops at its start
  for (const SolverEntry& solver : solvers()) {
    SolverState state = SolverState::at_start(model);
    const Summary summary = solver.run(model, state, spec, {}, {});
    EXPECT_EQ(summary.solver, solver.name);
    EXPECT_EQ(summary.converged(), solver.name != "newton") << solver.name << ": " << summary.message;
  }
}

TEST(SolverRegistry, ReadsAndSetsEachSolversStopSettings) {
  SolverSpec spec;
  spec.set_tolerance_N(2e-4);
  spec.set_tolerance_m(3e-5);
  spec.set_max_iterations(17);
  for (const SolverEntry& solver : solvers()) {
    const StopSettings stop = solver.stop_settings(spec);
    EXPECT_EQ(stop.tolerance_N, 2e-4) << solver.name;
    EXPECT_EQ(stop.tolerance_m, 3e-5) << solver.name;
    EXPECT_EQ(stop.max_iterations, 17) << solver.name;
  }
  solver_named("dynamic").set_stop_settings(spec, {5e-3, 0.0, 3});
  EXPECT_EQ(spec.dynamic.tolerance_N, 5e-3);
  EXPECT_EQ(spec.dynamic.max_iterations, 3);
  EXPECT_EQ(spec.relax.tolerance_N, 2e-4) << "the others keep theirs";
  spec.name = "dynamic";
  EXPECT_EQ(spec.tolerance_N(), 5e-3);
  EXPECT_EQ(spec.tolerance_m(), 0.0);
  spec.name = "relax";
  EXPECT_EQ(spec.tolerance_N(), 2e-4);
  spec.name = "simplex";
  EXPECT_THROW(spec.tolerance_N(), std::invalid_argument);
}

TEST(SolverRegistry, ChecksEachSolversOwnOptions) {
  SolverSpec spec;
  spec.newton.armijo = -1.0;
  for (const SolverEntry& solver : solvers()) {
    std::string field;
    const std::string why = solver.invalid_reason(spec, &field);
    EXPECT_EQ(why.empty(), solver.name != "newton") << solver.name << ": " << why;
    if (solver.name == "newton") {
      EXPECT_EQ(field, "armijo");
    }
  }
}

TEST(SolverRegistry, NamesHowEachEstimatesItsDistanceFromTheRest) {
  EXPECT_EQ(solver_named("newton").position_error_estimate, "newton_step");
  EXPECT_EQ(solver_named("relax").position_error_estimate, "convergence_rate");
  EXPECT_EQ(solver_named("dynamic").position_error_estimate, "convergence_rate");
}

}  // namespace
}  // namespace fabform::solver_registry_test
