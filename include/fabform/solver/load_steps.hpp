#pragma once
// Forming as it happens: the bodies travel along their paths (tool_path.hpp) in K load steps,
// and each step is solved to the tolerance from the rest of the one before, so that the
// history friction depends on is kept (where each node landed, how far it has slid).
// Step k moves each travelling body from its pose k−1 to its pose k and carries the fabric
// with it: a node resting on the body moves with it (with its friction anchor), and a node the
// body now overlaps is put on its surface where it is closest. The solver then finds the
// step's rest. Records are numbered within their step (IterationRecord::step), so a run's
// history is every step's convergence in turn.
#include <functional>

#include "fabform/model/model.hpp"
#include "fabform/solver/solve.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

/// Told when load step `step` has converged, with its rest state and its own summary.
using StepObserver = std::function<void(int step, const SolverState& state, const Summary& step_summary)>;

/// Moves the bodies to their poses after step `step` − 1 and the fabric with them
/// (step 1: from their placements).
void begin_load_step(Model& model, SolverState& state, int step);

/// Solves `model` step by step from `state` (std::invalid_argument when no body travels). Returns the run's
/// summary: every step's records in its history, the total iterations and seconds, and the
/// termination of the last step solved; a step that does not converge ends the run, its
/// message naming the step. `resumed` is a checkpoint's summary: the run goes on inside the
/// step its last record belongs to, `state` being that checkpoint's.
Summary solve_in_steps(Model& model, SolverState& state, const SolverSpec& spec, const IterationObserver& observer,
                       const StepObserver& step_done, Summary resumed = {});

}  // namespace fabform
