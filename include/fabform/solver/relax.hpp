#pragma once
// Seed 003's node-wise relaxation (García, Gómez, Ruiz, Boulanger 2006, §3.2–3.3), faithful:
// each node in turn (colour by colour, the checkerboard on a rectangle; the seed leaves the
// order open) moves along its
// resultant R by ξ = Σ|d_k| / C (Eq. 4–5); while the move does not reduce the node's residual,
// ξ is divided by C. A node pressed against a body slides
// along its tangent plane and is projected back onto the surface; it leaves when R points out
// of the body. Locked axes do not move. Stops when ‖V‖∞ ≤ e (Eq. 6) or at the iteration cap.
#include <string>

#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

struct RelaxOptions {
  double C = 2.0;               // seed 003's user constant: step divisor, in (1, 1e6]
  double tolerance_N = 1e-3;    // e > 0: stop when ‖V‖∞ ≤ e
  // > 0: stop too when the distance from the rest is estimated within it (m), whichever of the
  // two tolerances is met first (position_error.hpp); 0: e alone.
  double tolerance_m = 0.0;
  int max_iterations = 100000;  // cap on sweeps over all nodes
  // A node gives up for this sweep once ξ has shrunk below this fraction of its first value.
  double min_step_fraction = 1e-14;

  /// Why the options cannot be used, or "" when they can; `field` gets the option's name.
  std::string invalid_reason(std::string* field = nullptr) const;
};

/// Throws std::invalid_argument when options.invalid_reason() is not empty. `resumed` is the
/// summary of the run `state` was checkpointed from (see begin_summary).
Summary relax(const Model& model, SolverState& state, const RelaxOptions& options,
              const IterationObserver& observer = {}, Summary resumed = {});

}  // namespace fabform
