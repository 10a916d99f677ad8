#pragma once
// The bending of a hinge in the quadratic form of Bergou et al. 2006 for a flat rest state:
// E = B·s·|k|², s the hinge's shape factor and k = Σ wᵢ·pᵢ its bend vector over the edge's two
// nodes and the two far points, the weights being the four flat points' affine dependency
// (Σ wᵢ = 0, Σ wᵢ·qᵢ = 0). So k vanishes for every rigid or affine motion of the flat fabric,
// and a fold of one face by θ about the edge gives |k| = 2·sin(θ/2), E = 2·B·s·(1 − cos θ):
// exactly the discrete-shell energy (Grinspun et al. 2003), which is B·s·θ² for small θ, the
// continuum's B·κ²/2 per area. Unlike the dihedral angle, k is linear in the positions: the
// force is bounded where a face collapses (tension-only cells shrink for free, and a
// collapsing face's angle turns infinitely fast), and the Hessian 2·B·s·w·wᵀ is constant and
// positive semi-definite. For a deformation that is not isometric, a cell shrinking unevenly in
// its own plane, k is not zero: the hinge then resists the unevenness as well.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/hinge.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

/// The hinge's bend vector k = Σ wᵢ·pᵢ at x with node `moved` at `at` (none when moved is -1);
/// |k| = 2·sin(θ/2) for a fold by θ (dimensionless).
Eigen::Vector3d bend_vector(const Hinge& hinge, const std::vector<Eigen::Vector3d>& x, int moved = -1,
                            const Eigen::Vector3d& at = Eigen::Vector3d::Zero());

/// B·s·|k|² (J), node `moved` at `at`.
double hinge_energy(const Hinge& hinge, double rigidity_Nm, const std::vector<Eigen::Vector3d>& x,
                    int moved = -1, const Eigen::Vector3d& at = Eigen::Vector3d::Zero());

/// The nodes a hinge reaches (up to six, each once) and each one's weight in k = Σ cⱼ·xⱼ
/// (a far point's weight is shared by its two nodes): ∂k/∂xⱼ = cⱼ·I.
struct HingeStencil {
  std::array<int, 6> node{};
  std::array<double, 6> weight{};
  int count = 0;
};
HingeStencil hinge_stencil(const Hinge& hinge);
/// Where `node` stands in the stencil (it must be one of the hinge's nodes).
std::size_t stencil_index(const HingeStencil& stencil, int node);

/// The hinge's side in the flat fabric, from its first edge node to its second (m).
Eigen::Vector3d flat_side(const Model& model, const Hinge& hinge);

/// A property measured along warp and weft as the hinge bends with it: the warp's for an edge
/// along the weft, between them value_warp·cos²ψ + value_weft·sin²ψ, ψ the bending direction's
/// angle from the warp (see HingeBending).
double along_bending_direction(const Model& model, const Hinge& hinge, double value_warp, double value_weft);

/// The fabric's hinges as a term of the model, with its flexural rigidity B (N·m) along the warp
/// and along the weft (a strip cut along the warp and bent along its length resists with the
/// warp's). A hinge bends the fabric across its edge, so an edge along the weft takes the warp's
/// B; between, B_warp·cos²ψ + B_weft·sin²ψ, ψ the bending direction's angle from the warp: the
/// simplest orthotropic rule through both measured values (a measured bias value is not used).
class HingeBending final : public Term {
 public:
  explicit HingeBending(double rigidity_Nm) : rigidity_warp_Nm_(rigidity_Nm), rigidity_weft_Nm_(rigidity_Nm) {}
  HingeBending(double warp_Nm, double weft_Nm) : rigidity_warp_Nm_(warp_Nm), rigidity_weft_Nm_(weft_Nm) {}
  /// The rigidity a hinge bends with, from its edge's direction in the flat fabric.
  double rigidity_of(const Model& model, const Hinge& hinge) const;

  std::string describe(const Model& model) const override;
  /// −∂E/∂x_node = −Σ 2·B·s·c_node·k over the hinges that reach the node.
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  /// 2·B·s·(c_a·c_b)·I over each pair of the nodes a hinge reaches: exact, constant, positive
  /// semi-definite.
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  /// Per node, half its row sum of |2·B·s·c·cᵀ|, as a spring's k is to its block.
  void bound_stiffness(const Model& model, StiffnessBound& bound) const override;
  bool resists_bending() const override { return true; }

 private:
  /// The energy of the hinges that reach `node`, with it at `at`.
  double node_energy(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const;

  double rigidity_warp_Nm_;
  double rigidity_weft_Nm_;
};

}  // namespace fabform
