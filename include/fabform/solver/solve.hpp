#pragma once
// One entry point for every solver: the settings a scene's [solver] section gives, and the
// call that runs the solver they name.
#include <string>

#include "fabform/model/model.hpp"
#include "fabform/solver/dynamic.hpp"
#include "fabform/solver/newton.hpp"
#include "fabform/solver/relax.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

struct SolverSpec {
  std::string name = "relax";  // a solver of solver_registry.hpp
  RelaxOptions relax;          // used when name is "relax"
  NewtonOptions newton;        // used when name is "newton"
  DynamicOptions dynamic;      // used when name is "dynamic"
  int threads = 1;
  // e relative to the fabric's force scale (force_scale.hpp), when > 0: the run resolves it to
  // newtons once its model is built (set_tolerance_N).
  double tolerance_relative = 0.0;
  // Grid continuation (grid_continuation.hpp): at most this many coarser grids, each half the
  // last's divisions, solved first to give this grid its start; 0: none. Newton's alone.
  int continuation_levels = 0;

  /// Sets every solver's e (N).
  void set_tolerance_N(double tolerance_N);

  /// Sets every solver's distance tolerance (m; 0: none).
  void set_tolerance_m(double tolerance_m);

  /// Sets every solver's iteration cap.
  void set_max_iterations(int max_iterations);

  /// e of the solver the spec names (N). The tolerances throw std::invalid_argument for a name
  /// fabform does not know (solver_registry.hpp).
  double tolerance_N() const;

  /// The distance tolerance of the solver the spec names (m; 0: none).
  double tolerance_m() const;
};

/// Runs the named solver from `state`, going on from `resumed` when it is a checkpoint's. Throws std::invalid_argument for an unknown name or
/// options the solver refuses.
Summary solve(const Model& model, SolverState& state, const SolverSpec& spec,
              const IterationObserver& observer = {}, Summary resumed = {});

}  // namespace fabform
