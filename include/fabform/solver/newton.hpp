#pragma once
// A fast quasi-static solver reaching relax's equilibrium: Newton's method on the fabric's total
// potential energy Π(x) = Σ w·L·∫₀^ε T − Σ f·x (stretch, and constant loads such as its weight,
// which add nothing to the Hessian). Each spring's stiffness is projected positive
// semi-definite; the linear system, in each node's free directions (locked axes and the normal
// of the body a node presses on eliminated), regularised by μ·I, is solved by a sparse Cholesky
// factorisation (CHOLMOD) or, on large grids, by conjugate gradients preconditioned by multigrid
// (geometric on the fabric's lattice, hypre's BoomerAMG on an arc mesh) to a tolerance that
// tightens as the forces fall (inexact Newton); a backtracking line search on the energy moves
// the nodes as relax does (a node that would enter a body stops on it, a node on a body slides
// and is projected back, and leaves when its force points out). Progress is seed 003's ‖V‖∞, as
// relax measures it.
#include <string>

#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

struct NewtonOptions {
  double tolerance_N = 1e-3;  // e > 0: stop when ‖V‖∞ ≤ e
  // > 0: stop too when the distance from the rest is estimated within it (m), whichever of the
  // two tolerances is met first (position_error.hpp); 0: e alone.
  double tolerance_m = 0.0;
  int max_iterations = 200;   // cap on Newton steps (a converging run takes tens)
  // μ added to the matrix's diagonal, relative to its mean diagonal entry: keeps it definite
  // where springs are slack (zero stiffness). Raised ×10 while the step is poor, lowered back.
  double regularization = 1e-8;
  // What a slack spring (zero stiffness) keeps in Newton's matrix, as a share of its table's
  // steepest slope along it: nodes held mostly by slack springs then take measured steps
  // instead of near-singular ones. Changes the path, not the rest. 0: the exact matrix.
  double slack_stiffness = 0.0;
  double armijo = 1e-4;      // sufficient decrease: Π(x + Δx) ≤ Π(x) + armijo · ∇Π·Δx
  int max_backtracks = 60;   // step halvings before the line search is declared stalled
  // Friction's creep length ε as a fraction of the mean spring length: a node that slipped
  // less than ε from where it landed is stuck (friction smoothed as in incremental potential
  // contact, coulomb_friction.hpp).
  double friction_creep = 1e-2;
  // The linear solve of each step: "cholesky" (exact), "multigrid" (conjugate gradients
  // preconditioned by multigrid, to an inexact Newton tolerance), or "auto": the
  // factorisation below a size, multigrid from it (linalg/linear_solver.hpp says which and why).
  std::string linear_solver = "auto";
  // Whether the run ends with the estimate of its distance from the rest (one more solve);
  // a continuation's coarser grid, whose rest is only a start, goes without.
  bool final_estimate = true;

  /// Why the options cannot be used, or "" when they can; `field` gets the option's name.
  std::string invalid_reason(std::string* field = nullptr) const;
};

/// Throws std::invalid_argument when options.invalid_reason() is not empty. `resumed` is the
/// summary of the run `state` was checkpointed from (see begin_summary).
Summary newton(const Model& model, SolverState& state, const NewtonOptions& options,
               const IterationObserver& observer = {}, Summary resumed = {});

}  // namespace fabform
