#include "fabform/model/solver_needs.hpp"

namespace fabform {

std::string to_string(SolverNeed need) {
  switch (need) {
    case SolverNeed::velocity: return "a force that depends on the fabric's velocity";
    case SolverNeed::stick: return "friction's stick and slip";
    case SolverNeed::stiff_penalty: return "a stiffness far above the fabric's, taken into the step's matrix";
    case SolverNeed::no_time_step: return "a stiffness no stable time step bounds";
    case SolverNeed::loading_branch: return "hysteresis on its loading branch alone, along which nothing swings back";
  }
  return "";
}

std::string SolverNeeds::said() const {
  std::string text;
  for (const SolverNeed need : kEveryNeed)
    if (contains(need)) text += (text.empty() ? "" : " and ") + to_string(need);
  return text;
}

}  // namespace fabform
