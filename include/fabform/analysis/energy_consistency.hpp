#pragma once
// Whether a state has the energy its forces say. Newton's line search trusts that moving a node
// along its force lowers Π by |R|·δ to first order; a term whose energy jumps, or whose force is
// not its energy's derivative, stalls it there. Each free node (not on a body, its locked axes
// held) whose force is above kSmallestForceN is moved δ = 1e-9 m along its force and against it,
// and half the difference of the two changes of Π (each term's own, node_energy_change) is
// compared with −|R|·δ: the stiffness's part, Kδ²/2 in each, cancels, and a jump on either side
// shows. A node whose two differ by more than half of |R|·δ disagrees.
#include <string>
#include <vector>

#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"

namespace fabform {

/// Below this force the change over δ (1e-13 J) nears the rounding of the terms' energies
/// (~1e-15 J on a CAD die: a node whose force is 1e-6 N disagrees by rounding alone).
constexpr double kSmallestForceN = 1e-4;

struct EnergyDisagreement {
  int node = 0;
  double force_N = 0.0;
  double predicted_J = 0.0;  // −|R|·δ
  double measured_J = 0.0;   // half the difference of Π's changes at x ± δ along R
  std::string term;          // the term whose change differs most from its own force's prediction
};

struct EnergyConsistency {
  int checked = 0;                               // the free nodes with a force above kSmallestForceN
  std::vector<EnergyDisagreement> disagreeing;  // the largest gap first
};

/// Checks every free node of `state`; throws std::invalid_argument for a model with a force that
/// has no potential (wind's drag: its energy says nothing of it).
EnergyConsistency check_energy_consistency(const Model& model, const SolverState& state);

}  // namespace fabform
