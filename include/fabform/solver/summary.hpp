#pragma once
// What every solver returns: why it stopped, a message for people, and the history of the
// run iteration by iteration (the convergence plot engineers keep as a regression test).
#include <functional>
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
};

struct Summary {
  std::string solver;
  Termination termination = Termination::not_converged;
  std::string message;
  int iterations = 0;
  double residual_N = 0.0;
  double tolerance_N = 0.0;
  double seconds = 0.0;
  int worst_node = -1;  // where ‖V‖∞ is attained (or the first broken node)
  std::vector<IterationRecord> history;

  bool converged() const { return termination == Termination::converged; }
};

/// Called after each iteration (and once for the start, iteration 0).
using IterationObserver = std::function<void(const IterationRecord&)>;

/// The summary a solver starts from: empty for a fresh run, or the one of the run it resumes
/// (its iterations and history go on). Throws std::invalid_argument when `resumed` belongs to
/// another solver.
Summary begin_summary(const std::string& solver, double tolerance_N, Summary resumed = {});

/// Appends an iteration to the summary's history and totals (replacing the last record when it
/// has the same iteration: a resumed run re-measures the state it resumes from), tells the
/// observer, and sets the termination when the run stops here: a non-finite residual,
/// ‖V‖∞ ≤ e, `max_iterations` reached, or an interrupt requested. Returns whether it stops.
/// `worst_node` is where ‖V‖∞ is attained.
bool record_iteration(Summary& summary, const IterationRecord& record, int worst_node,
                      int max_iterations, const IterationObserver& observer);

/// The iterations a history holds: over its load steps, each step's last iteration.
int total_iterations(const std::vector<IterationRecord>& history);

/// The message for people that says why a run stopped with its termination.
std::string stop_message(const Summary& summary);

}  // namespace fabform
