#pragma once
// The friction in bending that KES-FB measures as hysteresis: bent and unbent between ±2.5 cm⁻¹,
// a fabric's moment per width traces a loop 2HB wide round its elastic line B·κ, the yarns'
// contacts slipping (Lahey & Heppler 2004). A drape bends each part of the fabric one way from
// flat, so it follows the loop's loading branch, M = B·κ + HB·sign κ with HB = 2HB / 2: past a
// small curvature the friction adds a constant moment HB per width against the bending. Taken as
// that branch's potential, E = HB·l·|θ| per hinge (the work of a moment HB per width over a side
// of length l turned by θ), with |k| = 2·sin(θ/2) for |θ| (hinge_bending.hpp). Its corner is a
// Huber rounding of |θ| below the angle a chosen curvature κ_r makes at the hinge (KES-FB does
// not report where a fabric slips): the friction moment grows from 0 to HB there, so the energy
// stays smooth for Newton, and below it the fabric sticks, a rigidity HB/κ_r.
// It is the loading branch only: unbending (the loop's other branch) is not modelled, so a
// fabric is not held where it has been, and dynamic, whose fabric would swing back along this
// branch, is refused. Like B·s·|k|², HB·l·|k| also resists a cell shrinking unevenly in its plane.
#include <string>

#include "fabform/fabric/hinge.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

/// The hinges' bending friction: KES's 2HB (moment per width, N·m/m = N) along warp and weft, and
/// the curvature (1/m) over which the friction moment rounds from 0 to HB.
class HingeFriction final : public Term {
 public:
  HingeFriction(double hysteresis_warp_N, double hysteresis_weft_N, double rounding_per_m);

  /// HB (half of 2HB) the hinge bends against, from its edge's direction in the flat fabric (N).
  double friction_moment_of(const Model& model, const Hinge& hinge) const;
  /// The angle at which the hinge's friction moment reaches HB: the rounding curvature times the
  /// hinge's bending length l / (2·s) (a hinge's curvature is 2·s·θ / l).
  double rounding_angle_of(const Model& model, const Hinge& hinge) const;
  /// HB·l·ρ(|k|), ρ the rounded |·| (J), node `moved` at `at`.
  double friction_energy(const Model& model, const Hinge& hinge, const Positions& x, int moved,
                         const Eigen::Vector3d& at) const;

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  /// HB·l·(c_a·c_b)·D over each pair of the hinge's nodes, D = I/ε inside the rounding and
  /// (I − k̂·k̂ᵀ)/|k| past it: exact, positive semi-definite.
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  /// Per node, half a bound of its row sum of |stiffness| at any state: D's rows sum to at most
  /// (1 + √3)/(2·ε) in absolute value.
  void bound_stiffness(const Model& model, StiffnessBound& bound) const override;
  bool resists_bending() const override { return true; }
  /// What it needs of its solver; the scene reader asks the same of a scene that would have it.
  static constexpr SolverNeeds kNeeds = SolverNeed::loading_branch;
  SolverNeeds needs() const override { return kNeeds; }

 private:
  double hysteresis_warp_N_;
  double hysteresis_weft_N_;
  double rounding_per_m_;
};

}  // namespace fabform
