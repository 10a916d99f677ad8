#pragma once
// The friction in shear that KES-FB1 measures as hysteresis: sheared to ±8° and back, a fabric's
// shear force per width traces a loop round its elastic line G·γ, 2HG wide at ±0.5°, its yarns
// turning against each other at their crossings. A drape shears each cell one way from flat, so it
// follows the loop's loading branch, T = G·γ + HG·sign γ with HG = 2HG / 2: the elastic part is
// the shear springs' (a measured G or a bias table), this term the friction, per four-sided cell
// E = A·HG·ρ(γ), A the cell's flat area and ρ a Huber rounding of |γ| over a chosen angle γ₀
// (KES-FB1 does not report where a fabric slips): below it the cell sticks, a shear rigidity
// HG/γ₀. The cell's shear angle is read from its diagonals' strains, γ = (ε₁ − ε₂)·L₁·L₂ / (2·A):
// on a lattice's rectangular cells exact to first order (a square's diagonals stretch by ±γ/2)
// and blind to stretch along warp or weft, which strains both diagonals alike; on a rhombus or
// a jittered or arc mesh's cells neither holds, so the scene refuses those meshes. The loading
// branch only: unshearing is not modelled, and dynamic, whose fabric would swing back along it,
// is refused. 2HG, the small-amplitude width, is one constant; 2HG5 is not used. The term joins
// a cell's four corners, which relax's colours keep apart because [shear]'s diagonal springs
// and the cell's sides join each pair.
#include <string>

#include "fabform/model/term.hpp"

namespace fabform {

class ShearFriction final : public Term {
 public:
  /// KES's 2HG (force per width, N/m) and the shear angle (radians) over which HG rounds in.
  ShearFriction(double hysteresis_N_m, double rounding_rad);

  /// The shear angle of four-sided face `face` at x (radians).
  double shear_angle(const Model& model, int face, const Positions& x) const;

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  /// A·HG·(ρ''·g·gᵀ + ρ'·∂²γ), g = ∂γ/∂x; of ∂²γ = s·(∂²ε₁ − ∂²ε₂) only the diagonal whose part
  /// is positive semi-definite at the sign of ρ' is kept, so the sum is positive semi-definite.
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  /// What it needs of its solver; the scene reader asks the same of a scene that would have it.
  static constexpr SolverNeeds kNeeds = SolverNeed::loading_branch;
  SolverNeeds needs() const override { return kNeeds; }

 private:
  double cell_energy(const Model& model, int face, const Positions& x, int moved, const Eigen::Vector3d& at) const;

  double hysteresis_N_m_;
  double rounding_rad_;
};

}  // namespace fabform
