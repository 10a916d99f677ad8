#include "fabform/solver/solve.hpp"

#include <utility>

#include "fabform/thread_count.hpp"

namespace fabform {

Summary solve(const Model& model, SolverState& state, const SolverSpec& spec,
              const IterationObserver& observer, Summary resumed) {
  use_threads(spec.threads);
  return solver_named(spec.name).run(model, state, spec, observer, std::move(resumed));
}

}  // namespace fabform
