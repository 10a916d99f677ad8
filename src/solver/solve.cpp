#include "fabform/solver/solve.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "fabform/solver/solver_registry.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {
namespace {

// Sets one stop setting in every solver's options, so that a scene stays the same whichever
// solver --solver names.
template <class Value>
void set_in_every_solver(SolverSpec& spec, Value StopSettings::*setting, Value value) {
  for (const SolverEntry& solver : solvers()) {
    StopSettings stop = solver.stop_settings(spec);
    stop.*setting = value;
    solver.set_stop_settings(spec, stop);
  }
}

}  // namespace

void SolverSpec::set_tolerance_N(double tolerance_N) {
  set_in_every_solver(*this, &StopSettings::tolerance_N, tolerance_N);
}

void SolverSpec::set_tolerance_m(double tolerance_m) {
  set_in_every_solver(*this, &StopSettings::tolerance_m, tolerance_m);
}

void SolverSpec::set_max_iterations(int max_iterations) {
  set_in_every_solver(*this, &StopSettings::max_iterations, max_iterations);
}

double SolverSpec::tolerance_N() const { return solver_named(name).stop_settings(*this).tolerance_N; }

double SolverSpec::tolerance_m() const { return solver_named(name).stop_settings(*this).tolerance_m; }

Summary solve(const Model& model, SolverState& state, const SolverSpec& spec,
              const IterationObserver& observer, Summary resumed) {
  use_threads(spec.threads);
  for (const auto& term : model.terms)
    if (const std::string why = term->refusal(spec.name); !why.empty()) throw std::invalid_argument(why);
  return solver_named(spec.name).run(model, state, spec, observer, std::move(resumed));
}

}  // namespace fabform
