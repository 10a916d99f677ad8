#include "fabform/solver/solver_registry.hpp"

#include <stdexcept>
#include <utility>

namespace fabform {
namespace {

// A row for the solver `run` whose options the spec keeps in its member `kOptions`.
template <auto kOptions, auto run>
SolverEntry entry(const char* name, const char* position_error_estimate, SolverNeeds gives) {
  return {name,
          [](const Model& model, SolverState& state, const SolverSpec& spec, const IterationObserver& observer,
             Summary resumed) { return run(model, state, spec.*kOptions, observer, std::move(resumed)); },
          [](const SolverSpec& spec) { return stop_settings(spec.*kOptions); },
          [](SolverSpec& spec, const StopSettings& stop) { set_stop_settings(spec.*kOptions, stop); },
          [](const SolverSpec& spec, std::string* field) { return (spec.*kOptions).invalid_reason(field); },
          position_error_estimate,
          gives};
}

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

// The parts of `model` that need more than `gives`, said one after another.
std::string needing_more(const Model& model, SolverNeeds gives) {
  std::string names;
  for (const NeedingPart& part : model.parts_needing())
    if (!gives.contains(part.needs)) names += (names.empty() ? "" : ", ") + part.name;
  return names;
}

}  // namespace

const std::vector<SolverEntry>& solvers() {
  static const std::vector<SolverEntry> table = {
      // Least capable first (solvers_giving reads the table backwards).
      // Seed 003's rule moves one node at a time along its force: no stick, but no time step.
      entry<&SolverSpec::relax, &relax>("relax", "convergence_rate",
                                        SolverNeed::no_time_step | SolverNeed::loading_branch),
      // An explicit time step: velocities and stick, bound by the stiffest spring, swinging back.
      entry<&SolverSpec::dynamic, &dynamic>("dynamic", "convergence_rate", SolverNeed::velocity | SolverNeed::stick),
      // The Hessian in every step: whatever is stiff, with stick; no velocities.
      entry<&SolverSpec::newton, &newton>("newton", "newton_step",
                                          SolverNeed::stick | SolverNeed::stiff_penalty | SolverNeed::no_time_step |
                                              SolverNeed::loading_branch),
  };
  return table;
}

const SolverEntry* find_solver(const std::string& name) {
  for (const SolverEntry& solver : solvers())
    if (solver.name == name) return &solver;
  return nullptr;
}

const SolverEntry& solver_named(const std::string& name) {
  if (const SolverEntry* solver = find_solver(name)) return *solver;
  throw std::invalid_argument("unknown solver '" + name + "'");
}

bool solver_gives(const std::string& name, SolverNeeds needs) {
  const SolverEntry* solver = find_solver(name);
  return solver != nullptr && solver->gives.contains(needs);
}

std::string solvers_giving(SolverNeeds needs) {
  std::string said;
  for (auto solver = solvers().rbegin(); solver != solvers().rend(); ++solver)
    if (solver->gives.contains(needs)) said += (said.empty() ? "" : " or ") + solver->name;
  return said;
}

std::string solver_refusal(const Model& model, const std::string& name) {
  const SolverNeeds needs = model.solver_needs();
  const SolverEntry& solver = solver_named(name);
  if (solver.gives.contains(needs)) return "";
  const std::string who = solvers_giving(needs);
  return needing_more(model, solver.gives) + ": the model needs " + (needs - solver.gives).said() + ", which " + name +
         " does not give" + (who.empty() ? " (no solver gives all it needs)" : ": use " + who);
}

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

}  // namespace fabform
