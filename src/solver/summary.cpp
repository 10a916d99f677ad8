#include "fabform/solver/summary.hpp"

namespace fabform {

std::string to_string(Termination termination) {
  switch (termination) {
    case Termination::converged: return "converged";
    case Termination::not_converged: return "not converged";
    case Termination::numerical_failure: return "numerical failure";
  }
  return "unknown";
}

}  // namespace fabform
