#pragma once
// One entry point for every solver: the call that runs the solver a scene's [solver] settings
// name (SolverSpec, solver_registry.hpp).
#include "fabform/model/model.hpp"
#include "fabform/solver/solver_registry.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

/// Runs the named solver from `state`, going on from `resumed` when it is a checkpoint's. Throws
/// std::invalid_argument for an unknown name, options the solver refuses, or a model it cannot
/// carry (solver_refusal).
Summary solve(const Model& model, SolverState& state, const SolverSpec& spec,
              const IterationObserver& observer = {}, Summary resumed = {});

}  // namespace fabform
