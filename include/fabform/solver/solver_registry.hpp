#pragma once
// The solvers fabform knows, in one table: each one's name, its run, and where a scene's
// [solver] settings (SolverSpec) keep its options. solve(), the spec's tolerances, the scene's
// checks, result.json and `fabform solvers` all read it, so a new solver is one row.
#include <string>
#include <vector>

#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/stop_settings.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

struct SolverSpec;

struct SolverEntry {
  std::string name;
  /// Runs the solver with the spec's options for it (see solve()).
  Summary (*run)(const Model& model, SolverState& state, const SolverSpec& spec, const IterationObserver& observer,
                 Summary resumed);
  /// The stop settings of the spec's options for it, read and set.
  StopSettings (*stop_settings)(const SolverSpec& spec);
  void (*set_stop_settings)(SolverSpec& spec, const StopSettings& stop);
  /// Why the spec's options for it cannot be used, or "" when they can; `field` gets the option's name.
  std::string (*invalid_reason)(const SolverSpec& spec, std::string* field);
  // How it estimates the distance from the rest (position_error.hpp), as result.json names it.
  std::string position_error_estimate;
};

/// Every solver, in the order `fabform solvers` lists them.
const std::vector<SolverEntry>& solvers();

/// The solver named `name`; null when fabform has none of that name.
const SolverEntry* find_solver(const std::string& name);

/// The solver named `name`; throws std::invalid_argument when fabform has none of that name.
const SolverEntry& solver_named(const std::string& name);

}  // namespace fabform
