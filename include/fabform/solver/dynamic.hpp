#pragma once
// The explicit damped dynamics of seeds 000 and 004, run until the fabric comes to rest: each
// node carries a mass, and every step is symplectic Euler with damping,
//   v ← (1 − f)·v + Δt·R/m,   x ← x + Δt·v,
// f the fraction of velocity lost per step (seed 000's friction). Δt is kept under the stability
// limit of the stiffest springs of the current tables. A node that would enter a body stops on
// it and loses the velocity that pointed in; a node on a body slides and is projected back, and
// leaves when its force points out, as in relax. Optionally, Provot's (1995) stretch limit
// shortens every spring stretched beyond (1 + τ)·L after each step (seed 000 uses τ = 0.1).
// Progress is seed 003's ‖V‖∞, so the run stops where relax and newton would.
#include <optional>
#include <string>
#include <vector>

#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

struct DynamicOptions {
  double tolerance_N = 1e-3;       // e > 0: stop when ‖V‖∞ ≤ e
  // > 0: stop too when the distance from the rest is estimated within it (m), whichever of the
  // two tolerances is met first (position_error.hpp); 0: e alone.
  double tolerance_m = 0.0;
  int max_iterations = 10'000'000;  // cap on time steps
  // Inertia only: the rest does not depend on it. A typical fabric's 200 g/m². Used when the
  // model has no weight; with gravity the fabric's own density moves it.
  double areal_density_kg_m2 = 0.2;
  // f in [0, 1); empty: 4 / (springs across the fabric), near critical damping of the
  // slowest mode of a taut grid, so the step count to rest grows with the grid's size, not its square.
  std::optional<double> damping;
  double time_step_fraction = 0.9;  // Δt as a fraction of the stability limit, in (0, 1]
  double stretch_limit = 0.0;       // Provot's τ: 0 = off, else springs are kept ≤ (1 + τ)·L

  /// Why the options cannot be used, or "" when they can; `field` gets the option's name.
  std::string invalid_reason(std::string* field = nullptr) const;
};

/// Each node's mass (kg): the areal density times the fabric area the node stands for, its
/// faces' areas shared equally among their corners (a cell inside, half on an edge).
std::vector<double> node_masses(const Model& model, double areal_density_kg_m2);

/// The mass per area the dynamics moves (kg/m²): the fabric's when its weight is modelled, so
/// that it falls at g; else the options' (inertia only, the rest does not depend on it).
double inertia_density(const Model& model, const DynamicOptions& options);

struct TimeStep {
  double seconds = 0.0;          // Δt used: the fraction of stability_limit
  double stability_limit = 0.0;  // min over nodes of √(2m / Σ k) (Gershgorin bound on ω_max)
  double seed_limit = 0.0;       // seed 004's π√(m/k), k the stiffest spring, m the lightest node
};

/// The step for these masses: a spring's stiffness is w·T'/L with T' the steepest slope of its
/// table, which bounds its stiffness at every strain (along it, and across it, T/l ≤ T'/L).
TimeStep stable_time_step(const Model& model, const std::vector<double>& masses, double fraction);

/// Throws std::invalid_argument when options.invalid_reason() is not empty. `resumed` is the
/// summary of the run `state` was checkpointed from (see begin_summary).
Summary dynamic(const Model& model, SolverState& state, const DynamicOptions& options,
                const IterationObserver& observer = {}, Summary resumed = {});

}  // namespace fabform
