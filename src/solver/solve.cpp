#include "fabform/solver/solve.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "fabform/thread_count.hpp"

namespace fabform {

Summary solve(const Model& model, SolverState& state, const SolverSpec& spec,
              const IterationObserver& observer, Summary resumed) {
  use_threads(spec.threads);
  for (const auto& term : model.terms)
    if (const std::string why = term->refusal(spec.name); !why.empty()) throw std::invalid_argument(why);
  if (spec.name == "relax") return relax(model, state, spec.relax, observer, std::move(resumed));
  if (spec.name == "newton") return newton(model, state, spec.newton, observer, std::move(resumed));
  if (spec.name == "dynamic") return dynamic(model, state, spec.dynamic, observer, std::move(resumed));
  throw std::invalid_argument("unknown solver '" + spec.name + "'");
}

}  // namespace fabform
