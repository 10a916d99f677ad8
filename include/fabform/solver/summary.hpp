#pragma once
// What every solver returns: why it stopped, a message for people, and the history of the
// run iteration by iteration (the convergence plot engineers keep as a regression test).
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace fabform {

// `interrupted`: SIGINT or SIGTERM asked the run to stop (see interrupt.hpp). `running` is never
// a solver's: it marks the summary of a checkpoint written while the run went on.
enum class Termination { converged, not_converged, numerical_failure, interrupted, running };

/// "converged", "not converged", "numerical failure", "interrupted", "running".
std::string to_string(Termination termination);

struct IterationRecord {
  int iteration = 0;  // counted within its load step
  double residual_N = 0.0;  // ‖V‖∞ after the iteration
  double seconds = 0.0;     // since the solve started
  int contact_nodes = 0;
  int step = 0;  // the load step (load_steps.hpp) it belongs to; 0 for a run without travel
  // Made while its load step was being cut: the bodies stand at a part of the step, a pose a
  // checkpoint cannot record, so none is written from it.
  bool inside_cut = false;
};

// Which tolerance a converged run met: e in newtons, or the distance from the rest in metres.
enum class StopCriterion { none, force, position };

/// "tolerance_N", "tolerance_m", or "" for none.
std::string to_string(StopCriterion criterion);

struct Summary {
  std::string solver;
  Termination termination = Termination::not_converged;
  StopCriterion converged_on = StopCriterion::none;
  std::string message;
  int iterations = 0;
  double residual_N = 0.0;
  double tolerance_N = 0.0;
  double tolerance_m = 0.0;  // the distance tolerance; 0: none (e alone stops the run)
  // The estimate of the largest node distance from the exact rest at the final state
  // (position_error.hpp); NaN when not estimated (a broken or interrupted run).
  double position_error_m = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;
  // Newton's linear solve: "cholesky" or "multigrid" ("" for the other solvers), and the
  // multigrid's conjugate-gradient iterations over the run (since it resumed, for a resumed one).
  std::string linear_solver;
  long linear_iterations = 0;
  int worst_node = -1;  // where ‖V‖∞ is attained (or the first broken node)
  std::vector<IterationRecord> history;

  bool converged() const { return termination == Termination::converged; }
};

/// Called after each iteration (and once for the start, iteration 0).
using IterationObserver = std::function<void(const IterationRecord&)>;

/// The summary a solver starts from: empty for a fresh run, or the one of the run it resumes
/// (its iterations and history go on). Throws std::invalid_argument when `resumed` belongs to
/// another solver. `tolerance_m` > 0 lets the run stop on its distance from the rest too.
Summary begin_summary(const std::string& solver, double tolerance_N, Summary resumed = {},
                      double tolerance_m = 0.0);

/// Appends an iteration to the summary's history and totals (replacing the last record when it
/// has the same iteration: a resumed run re-measures the state it resumes from), tells the
/// observer, and sets the termination when the run stops here: a non-finite residual,
/// ‖V‖∞ ≤ e, `max_iterations` reached, or an interrupt requested. Returns whether it stops.
/// `worst_node` is where ‖V‖∞ is attained.
bool record_iteration(Summary& summary, const IterationRecord& record, int worst_node,
                      int max_iterations, const IterationObserver& observer);

/// Records the estimate of the distance from the rest at the state last recorded, and ends the
/// run converged on it when the summary has a tolerance_m and the estimate is within it (the two
/// tolerances stop a run whichever is met first). Returns whether it stops.
bool record_position_error(Summary& summary, double position_error_m);

/// Whether the run's final state still wants its estimate: it ended converged on e or at its
/// cap (a broken or interrupted run is not estimated; one stopped on tolerance_m already is).
bool final_position_error_due(const Summary& summary);

/// A warning when a run with a tolerance_m converged on e first, its estimate still beyond it;
/// "" otherwise.
std::string position_tolerance_warning(const Summary& summary);

/// The iterations a history holds: over its load steps, each step's last iteration.
int total_iterations(const std::vector<IterationRecord>& history);

/// The message for people that says why a run stopped with its termination.
std::string stop_message(const Summary& summary);

}  // namespace fabform
