#include "fabform/solver/summary.hpp"

#include <cmath>
#include <sstream>

namespace fabform {

std::string to_string(Termination termination) {
  switch (termination) {
    case Termination::converged: return "converged";
    case Termination::not_converged: return "not converged";
    case Termination::numerical_failure: return "numerical failure";
  }
  return "unknown";
}

bool record_iteration(Summary& summary, const IterationRecord& record, int worst_node,
                      int max_iterations, const IterationObserver& observer) {
  summary.history.push_back(record);
  if (observer) observer(record);
  summary.iterations = record.iteration;
  summary.residual_N = record.residual_N;
  summary.worst_node = worst_node;
  summary.seconds = record.seconds;
  if (!std::isfinite(record.residual_N)) summary.termination = Termination::numerical_failure;
  else if (record.residual_N <= summary.tolerance_N) summary.termination = Termination::converged;
  else if (record.iteration >= max_iterations) summary.termination = Termination::not_converged;
  else return false;
  return true;
}

std::string stop_message(const Summary& s) {
  std::ostringstream text;
  text.precision(3);
  if (s.termination == Termination::converged)
    text << "||V||inf = " << s.residual_N << " N <= e = " << s.tolerance_N << " N after "
         << s.iterations << " iterations";
  else if (s.termination == Termination::numerical_failure)
    text << "non-finite residual at node " << s.worst_node << " in iteration " << s.iterations;
  else
    text << "iteration cap " << s.iterations << " reached with ||V||inf = " << s.residual_N
         << " N > e = " << s.tolerance_N << " N (worst node " << s.worst_node << ")";
  return text.str();
}

}  // namespace fabform
