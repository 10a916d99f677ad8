#include "fabform/solver/summary.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fabform/solver/interrupt.hpp"

namespace fabform {

std::string to_string(Termination termination) {
  switch (termination) {
    case Termination::converged: return "converged";
    case Termination::not_converged: return "not converged";
    case Termination::numerical_failure: return "numerical failure";
    case Termination::interrupted: return "interrupted";
    case Termination::running: return "running";
  }
  return "unknown";
}

std::string to_string(StopCriterion criterion) {
  switch (criterion) {
    case StopCriterion::force: return "tolerance_N";
    case StopCriterion::position: return "tolerance_m";
    case StopCriterion::none: return "";
  }
  return "";
}

Summary begin_summary(const std::string& solver, double tolerance_N, Summary resumed, double tolerance_m) {
  if (!resumed.solver.empty() && resumed.solver != solver)
    throw std::invalid_argument("a run of " + resumed.solver + " cannot be resumed by " + solver);
  resumed.solver = solver;
  resumed.tolerance_N = tolerance_N;
  resumed.tolerance_m = tolerance_m;
  resumed.termination = Termination::not_converged;
  resumed.converged_on = StopCriterion::none;
  resumed.position_error_m = std::nan("");
  resumed.message.clear();
  return resumed;
}

bool record_iteration(Summary& summary, const IterationRecord& record, int worst_node,
                      int max_iterations, const IterationObserver& observer) {
  if (!summary.history.empty() && summary.history.back().iteration == record.iteration)
    summary.history.back() = record;
  else
    summary.history.push_back(record);
  if (observer) observer(record);
  summary.iterations = record.iteration;
  summary.residual_N = record.residual_N;
  summary.worst_node = worst_node;
  summary.seconds = record.seconds;
  if (!std::isfinite(record.residual_N)) summary.termination = Termination::numerical_failure;
  else if (record.residual_N <= summary.tolerance_N)
    summary.termination = Termination::converged, summary.converged_on = StopCriterion::force;
  else if (record.iteration >= max_iterations) summary.termination = Termination::not_converged;
  else if (interrupt_signal() != 0) summary.termination = Termination::interrupted;
  else return false;
  return true;
}

bool record_position_error(Summary& summary, double position_error_m) {
  summary.position_error_m = position_error_m;
  if (!(summary.tolerance_m > 0.0 && position_error_m <= summary.tolerance_m)) return false;
  summary.termination = Termination::converged;
  summary.converged_on = StopCriterion::position;
  return true;
}

bool final_position_error_due(const Summary& s) {
  return (s.termination == Termination::converged || s.termination == Termination::not_converged) &&
         s.converged_on != StopCriterion::position;
}

std::string position_tolerance_warning(const Summary& s) {
  if (!(s.tolerance_m > 0.0 && s.converged_on == StopCriterion::force && s.position_error_m > s.tolerance_m))
    return "";
  std::ostringstream text;
  text.precision(3);
  text << "the run met e = " << s.tolerance_N << " N first; its distance from the rest is estimated at "
       << s.position_error_m << " m, beyond tolerance_m = " << s.tolerance_m
       << " m: give a smaller e (--tol) for the distance to stop it";
  return text.str();
}

int total_iterations(const std::vector<IterationRecord>& history) {
  int total = 0;
  for (std::size_t i = 0; i < history.size(); ++i)
    if (i + 1 == history.size() || history[i + 1].step != history[i].step) total += history[i].iteration;
  return total;
}

std::string stop_message(const Summary& s) {
  std::ostringstream text;
  text.precision(3);
  if (s.termination == Termination::converged && s.converged_on == StopCriterion::position)
    text << "distance from the rest estimated at " << s.position_error_m << " m <= " << s.tolerance_m
         << " m after " << s.iterations << " iterations (||V||inf = " << s.residual_N << " N)";
  else if (s.termination == Termination::converged)
    text << "||V||inf = " << s.residual_N << " N <= e = " << s.tolerance_N << " N after "
         << s.iterations << " iterations";
  else if (s.termination == Termination::numerical_failure)
    text << "NaN or Inf at node " << s.worst_node << " in iteration " << s.iterations;
  else if (s.termination == Termination::interrupted)
    text << "interrupted by signal " << interrupt_signal() << " after iteration " << s.iterations
         << " with ||V||inf = " << s.residual_N << " N";
  else if (s.termination == Termination::running)
    text << "checkpoint after iteration " << s.iterations << " with ||V||inf = " << s.residual_N
         << " N; the run was still going";
  else
    text << "iteration cap " << s.iterations << " reached with ||V||inf = " << s.residual_N
         << " N > e = " << s.tolerance_N << " N (worst node " << s.worst_node << ")";
  return text.str();
}

}  // namespace fabform
