#include "fabform/solver/solve.hpp"

#include <stdexcept>
#include <utility>

#include "fabform/thread_count.hpp"

namespace fabform {

Summary solve(const Model& model, SolverState& state, const SolverSpec& spec,
              const IterationObserver& observer, Summary resumed) {
  use_threads(spec.threads);
  if (model.wind && spec.name != "dynamic")
    throw std::invalid_argument("wind depends on the fabric's velocity (seed 004): only solver dynamic models it, not " +
                                spec.name);
  if (spec.name == "relax") return relax(model, state, spec.relax, observer, std::move(resumed));
  if (spec.name == "newton") return newton(model, state, spec.newton, observer, std::move(resumed));
  if (spec.name == "dynamic") return dynamic(model, state, spec.dynamic, observer, std::move(resumed));
  throw std::invalid_argument("unknown solver '" + spec.name + "'");
}

}  // namespace fabform
