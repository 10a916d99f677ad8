// The solver dispatch: each name runs its solver, and a model only some solvers can take is
// refused by the others.
#include "fabform/solver/solve.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "fabform/model/wind.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::solve_test {
namespace {

TEST(Solve, RunsTheNamedSolver) {
  const Model model = test::clamped_fabric(4, 0.01);
  for (const char* name : {"relax", "dynamic", "newton"}) {
    SolverState state = SolverState::at_start(model);
    SolverSpec spec;
    spec.name = name;
    EXPECT_EQ(solve(model, state, spec).solver, name);
  }
  SolverState state = SolverState::at_start(model);
  SolverSpec spec;
  spec.name = "simplex";
  EXPECT_THROW(solve(model, state, spec), std::invalid_argument);
}

// Wind depends on the fabric's velocity and has no potential: only dynamic models it.
TEST(Solve, WindIsForDynamicOnly) {
  Model model = test::clamped_fabric(4, 0.01);
  model.terms.push_back(std::make_shared<WindLoad>(Wind{{0, 0, 3}, 1.0}));
  for (const char* name : {"relax", "newton"}) {
    SolverState state = SolverState::at_start(model);
    SolverSpec spec;
    spec.name = name;
    EXPECT_THROW(solve(model, state, spec), std::invalid_argument) << name;
  }
  SolverState state = SolverState::at_start(model);
  SolverSpec spec;
  spec.name = "dynamic";
  const Summary summary = solve(model, state, spec);
  EXPECT_TRUE(summary.converged()) << summary.message;
  EXPECT_GT(summary.iterations, 0) << "the wind moves the fabric";
}

}  // namespace
}  // namespace fabform::solve_test
