#include "fabform/solver/solve.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "fabform/thread_count.hpp"

namespace fabform {

Summary solve(const Model& model, SolverState& state, const SolverSpec& spec,
              const IterationObserver& observer, Summary resumed) {
  use_threads(spec.threads);
  if (const std::string why = solver_refusal(model, spec.name); !why.empty()) throw std::invalid_argument(why);
  return solver_named(spec.name).run(model, state, spec, observer, std::move(resumed));
}

}  // namespace fabform
