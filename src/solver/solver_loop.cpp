#include "fabform/solver/solver_loop.hpp"

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "fabform/solver/position_error.hpp"

namespace fabform {

Summary run_solver_loop(const std::string& solver, const StopSettings& stop, const SolverSteps& steps,
                        const IterationObserver& observer, Summary resumed,
                        std::chrono::steady_clock::time_point started) {
  Summary summary = begin_summary(solver, stop.tolerance_N, std::move(resumed), stop.tolerance_m);
  const int first = summary.iterations;
  const double earlier_seconds = summary.seconds;
  const auto elapsed = [&] {
    return earlier_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  for (int iteration = first;; ++iteration) {
    const StepOutcome outcome = iteration > first ? steps.step(summary) : StepOutcome::moved;
    if (outcome == StepOutcome::stopped) break;
    const StateResidual m = steps.measure();
    if (outcome == StepOutcome::stalled && std::isfinite(m.max_residual_N)) {  // a broken state is recorded below
      summary.termination = Termination::not_converged;
      summary.seconds = elapsed();
      summary.message = steps.stall_message(summary);
      return summary;
    }
    const IterationRecord record{iteration, m.max_residual_N, elapsed(), m.contact_nodes};
    if (record_iteration(summary, record, m.worst_node, stop.max_iterations, observer)) break;
  }
  if (steps.final_position_error && final_position_error_due(summary))
    summary.position_error_m = steps.final_position_error(summary);
  summary.seconds = elapsed();  // the final estimate included (newton's is one more factorisation)
  summary.message = stop_message(summary);
  return summary;
}

SolverSteps rate_estimated_steps(const SolverState& state, double tolerance_m, std::function<void()> advance,
                                 std::function<StateResidual()> measure) {
  // The positions before the last move; shared by the steps, which outlive this call.
  const auto before = std::make_shared<std::vector<Eigen::Vector3d>>();
  const auto distance = [before, &state](const Summary& summary) {
    return before->empty() ? std::nan("") : rate_position_error(summary.history, largest_move(*before, state.x));
  };
  const auto step = [=, &state, advance = std::move(advance)](Summary& summary) {
    if (tolerance_m > 0.0 && record_position_error(summary, distance(summary))) return StepOutcome::stopped;
    *before = state.x;
    advance();
    return StepOutcome::moved;
  };
  return {step, std::move(measure), distance, {}};
}

}  // namespace fabform
