// The table of solvers: each row runs its own solver with its own options from the spec, and
// the spec's tolerances are read from the named solver's options and set in every solver's; what
// each solver gives the terms that need it, and the one check that refuses a model a solver cannot
// carry, wherever the solve starts.
#include "fabform/solver/solver_registry.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fabform/solver/solve.hpp"
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

TEST(SolverRegistry, DeclaresWhatEachSolverGives) {
  EXPECT_TRUE(solver_gives("dynamic", SolverNeed::velocity));
  EXPECT_FALSE(solver_gives("newton", SolverNeed::velocity));
  EXPECT_FALSE(solver_gives("relax", SolverNeed::stick));
  EXPECT_TRUE(solver_gives("dynamic", SolverNeed::stick));
  EXPECT_FALSE(solver_gives("dynamic", SolverNeed::no_time_step));
  EXPECT_FALSE(solver_gives("dynamic", SolverNeed::loading_branch));
  EXPECT_TRUE(solver_gives("relax", SolverNeed::no_time_step | SolverNeed::loading_branch));
  EXPECT_TRUE(solver_gives("newton", SolverNeed::stick | SolverNeed::stiff_penalty | SolverNeed::no_time_step |
                                         SolverNeed::loading_branch));
  for (const SolverEntry& solver : solvers()) EXPECT_TRUE(solver_gives(solver.name, SolverNeeds())) << solver.name;
  EXPECT_FALSE(solver_gives("simplex", SolverNeeds()));
}

TEST(SolverRegistry, SaysWhichSolversGiveANeedTheMostCapableFirst) {
  EXPECT_EQ(solvers_giving(SolverNeed::stick), "newton or dynamic");
  EXPECT_EQ(solvers_giving(SolverNeed::loading_branch), "newton or relax");
  EXPECT_EQ(solvers_giving(SolverNeed::velocity), "dynamic");
  EXPECT_EQ(solvers_giving(SolverNeed::stick | SolverNeed::stiff_penalty), "newton");
  EXPECT_EQ(solvers_giving(SolverNeed::velocity | SolverNeed::stiff_penalty), "");
  EXPECT_EQ(solvers_giving(SolverNeeds()), "newton or dynamic or relax");
}

// A term that asks for what it is given and does nothing else.
class Needy final : public Term {
 public:
  explicit Needy(SolverNeeds needs) : needs_(needs) {}
  std::string describe(const Model&) const override { return "needy"; }
  Eigen::Vector3d force_at(const Model&, const Positions&, int, const Eigen::Vector3d&) const override {
    return Eigen::Vector3d::Zero();
  }
  double energy(const Model&, const Positions&) const override { return 0.0; }
  double node_energy_change(const Model&, const Positions&, int, const Eigen::Vector3d&) const override { return 0.0; }
  SolverNeeds needs() const override { return needs_; }

 private:
  SolverNeeds needs_;
};

TEST(SolverRegistry, RefusesAModelWhoseNeedsItLacksWhereverTheSolveStarts) {
  Model model = test::clamped_fabric(4, 0.01);
  model.terms.push_back(std::make_shared<Needy>(SolverNeed::velocity));
  EXPECT_EQ(solver_refusal(model, "dynamic"), "");
  const std::string said =
      "needy: the model needs a force that depends on the fabric's velocity, which newton does not give: use dynamic";
  EXPECT_EQ(solver_refusal(model, "newton"), said);
  SolverState state = SolverState::at_start(model);
  SolverSpec spec;
  spec.name = "newton";
  try {
    solve(model, state, spec);
    ADD_FAILURE() << "solved";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()), "newton: " + said);
  }
  try {
    newton(model, state, spec.newton);
    ADD_FAILURE() << "solved";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()), "newton: " + said);
  }
  EXPECT_THROW(relax(model, state, spec.relax), std::invalid_argument);
  model.terms.push_back(std::make_shared<Needy>(SolverNeed::stiff_penalty));
  EXPECT_EQ(solver_refusal(model, "dynamic"),
            "needy: the model needs a stiffness far above the fabric's, taken into the step's matrix, which dynamic "
            "does not give (no solver gives all it needs)");
  EXPECT_EQ(solver_refusal(model, "newton"),
            "needy: the model needs a force that depends on the fabric's velocity, which newton does not give (no "
            "solver gives all it needs)");
}

}  // namespace
}  // namespace fabform::solver_registry_test
