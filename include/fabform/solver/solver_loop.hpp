#pragma once
// The loop every solver runs. It measures each state and records it (history, observer,
// interrupt, iteration cap, e: record_iteration), counts the seconds on from a resumed run's,
// estimates the final state's distance from the rest, and words why the run stopped. What
// differs between solvers comes in as their steps: how one moves the state an iteration on
// (and checks the state last recorded against tolerance_m first, each its own way), how it
// measures a state, and how it estimates the distance from the rest.
#include <chrono>
#include <functional>
#include <string>

#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/stop_settings.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

/// What a solver's step did from the state last recorded.
enum class StepOutcome {
  moved,    // the state is the next iteration's
  stalled,  // no move was acceptable: the state is unchanged, and the run ends there
  stopped,  // the state last recorded is within tolerance_m (record_position_error): the run ends
};

/// What one solver does within the loop.
struct SolverSteps {
  /// Moves the state one iteration on, unless the state last recorded ends the run.
  std::function<StepOutcome(Summary&)> step;
  /// ‖V‖∞, its worst node and the contact of the current state.
  std::function<StateResidual()> measure;
  /// The estimate of the final state's distance from the rest (m; NaN: none), asked for when
  /// final_position_error_due; empty: none asked for.
  std::function<double(const Summary&)> final_position_error;
  /// The message for a run whose step stalled; a solver whose steps never stall leaves it empty.
  std::function<std::string(const Summary&)> stall_message;
};

/// Runs a solver's iterations from `resumed` (begin_summary) until record_iteration or a step
/// ends the run. The seconds count from `started` (the solver's start, its set-up included) on
/// top of the resumed run's. Returns the summary, its message said.
Summary run_solver_loop(const std::string& solver, const StopSettings& stop, const SolverSteps& steps,
                        const IterationObserver& observer, Summary resumed,
                        std::chrono::steady_clock::time_point started);

/// The steps of a solver without a matrix to estimate from (relax, dynamic): before each move
/// the state last recorded is checked against tolerance_m by rate_position_error, from the
/// largest node move that reached it; `advance` moves the state (it never stalls).
SolverSteps rate_estimated_steps(const SolverState& state, double tolerance_m, std::function<void()> advance,
                                 std::function<StateResidual()> measure);

}  // namespace fabform
