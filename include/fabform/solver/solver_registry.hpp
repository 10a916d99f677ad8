#pragma once
// The solvers fabform knows, in one table, and a scene's [solver] settings for them
// (SolverSpec): each solver's name, its run, and where the spec keeps its options. solve(), the
// spec's tolerances, the scene's checks, result.json and `fabform solvers` all read the table,
// so a new solver is one row and its options in the spec.
#include <string>
#include <vector>

#include "fabform/model/model.hpp"
#include "fabform/solver/dynamic.hpp"
#include "fabform/solver/newton.hpp"
#include "fabform/solver/relax.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/stop_settings.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

struct SolverSpec {
  std::string name = "relax";  // a solver of solvers()
  RelaxOptions relax;          // used when name is "relax"
  NewtonOptions newton;        // used when name is "newton"
  DynamicOptions dynamic;      // used when name is "dynamic"
  int threads = 1;
  // e relative to the fabric's force scale (force_scale.hpp), when > 0: the run resolves it to
  // newtons once its model is built (set_tolerance_N).
  double tolerance_relative = 0.0;
  // Grid continuation (run/coarse_grid_start.hpp): at most this many coarser grids, each half the
  // last's divisions, solved first to give this grid its start; 0: none. Newton's alone. A scene
  // that gives none gets fabform's choice from its fabric's size (chosen_continuation_levels).
  int continuation_levels = 0;
  bool continuation_chosen = false;  // fabform chose continuation_levels, not the scene
  // A load step that does not converge (load_steps.hpp) is cut in half and solved again, a half
  // that does not is cut again, down to 1/2^max_step_cuts of the step; 0: never cut. 0 … 20.
  int max_step_cuts = 4;

  /// Sets every solver's e (N).
  void set_tolerance_N(double tolerance_N);

  /// Sets every solver's distance tolerance (m; 0: none).
  void set_tolerance_m(double tolerance_m);

  /// Sets every solver's iteration cap.
  void set_max_iterations(int max_iterations);

  /// e of the solver the spec names (N). The tolerances throw std::invalid_argument for a name
  /// fabform does not know.
  double tolerance_N() const;

  /// The distance tolerance of the solver the spec names (m; 0: none).
  double tolerance_m() const;
};

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
  // What it gives the terms and features that need it (solver_needs.hpp).
  SolverNeeds gives;
};

/// Every solver, in the order `fabform solvers` lists them.
const std::vector<SolverEntry>& solvers();

/// The solver named `name`; null when fabform has none of that name.
const SolverEntry* find_solver(const std::string& name);

/// The solver named `name`; throws std::invalid_argument when fabform has none of that name.
const SolverEntry& solver_named(const std::string& name);

/// Whether solver `name` gives every need of `needs` (false for a name fabform does not know).
bool solver_gives(const std::string& name, SolverNeeds needs);

/// The solvers that give every need of `needs`, the most capable first (the table backwards):
/// "newton or relax".
std::string solvers_giving(SolverNeeds needs);

/// Why solver `name` cannot solve `model`: what in the model needs what it does not give, and
/// which solvers give it; "" when it can. Throws std::invalid_argument for an unknown name. The
/// solvers ask it on entry.
std::string solver_refusal(const Model& model, const std::string& name);

}  // namespace fabform
