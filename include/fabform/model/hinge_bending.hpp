#pragma once
// The discrete-shell bending of a hinge: its energy E = 2·B·s·(1 − cos θ), s the hinge's shape
// factor and θ its dihedral angle (0 in the flat fabric), which is B·s·θ² for small θ, the
// continuum's B·κ²/2 per area (Grinspun et al. 2003), and stays smooth and bounded where a
// fold closes (θ → ±π) on a mesh cell; the gradient of θ (Bridson et al. 2003); and a positive
// semi-definite stiffness 2·B·s·max(cos θ, 0)·∇θ∇θᵀ (the Gauss–Newton part of E's Hessian).
#include <array>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/hinge.hpp"
#include "fabform/model/model.hpp"

namespace fabform {

/// The hinge's four points: its edge's two nodes and each face's far point, with node `moved`
/// at `at` (none when moved is -1).
std::array<Eigen::Vector3d, 4> hinge_points(const Hinge& hinge, const std::vector<Eigen::Vector3d>& x,
                                            int moved = -1, const Eigen::Vector3d& at = Eigen::Vector3d::Zero());

/// Signed dihedral angle θ in (−π, π] across the edge; 0 when both faces lie in one plane,
/// and 0 as well where a face has collapsed to a line (it has no normal).
double dihedral_angle(const std::array<Eigen::Vector3d, 4>& p);

/// ∂θ/∂p for the four points (zero where a face has collapsed).
std::array<Eigen::Vector3d, 4> dihedral_angle_gradient(const std::array<Eigen::Vector3d, 4>& p);

/// 2·B·s·(1 − cos θ) (J), node `moved` at `at`.
double hinge_energy(const Hinge& hinge, double rigidity_Nm, const std::vector<Eigen::Vector3d>& x,
                    int moved = -1, const Eigen::Vector3d& at = Eigen::Vector3d::Zero());

/// The hinge's angle θ, the nodes it reaches (up to six, each once) and ∂θ/∂x for each.
struct HingeGradient {
  double theta = 0.0;
  std::array<int, 6> node{};
  std::array<Eigen::Vector3d, 6> d_theta{};
  int count = 0;
};
HingeGradient hinge_gradient(const Hinge& hinge, const std::vector<Eigen::Vector3d>& x, int moved = -1,
                             const Eigen::Vector3d& at = Eigen::Vector3d::Zero());

/// The model's bending: the sum over its fabric's hinges (0 without bending rigidity).
double bending_energy(const Model& model, const std::vector<Eigen::Vector3d>& x);
/// The hinges' force on `node` placed at `at`, −∂E/∂x_node.
Eigen::Vector3d bending_force_at(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                                 const Eigen::Vector3d& at);
/// The energy of the hinges that reach `node`, with it at `at`.
double node_bending_energy(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                           const Eigen::Vector3d& at);

}  // namespace fabform
