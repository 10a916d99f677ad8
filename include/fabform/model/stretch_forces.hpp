#pragma once
// The stretch term of seed 003's Eq. (1): the resultant R of the warp and weft springs around
// a node (Eq. 3) with the node's constant load added (so R is every force on it), and the
// springs' deformations d_k that set the relaxation step (Eq. 4). stretch_energy is the
// springs' alone; the loads' potential is in external_loads.hpp, the sum in potential_energy.hpp.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// R at `node` with the node moved to `at` and every other node where `x` has it: its springs'
/// and hinges' forces, its constant load and the wind on it at rest (wind.hpp).
Eigen::Vector3d node_force_at(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                              const Eigen::Vector3d& at);

inline Eigen::Vector3d node_force(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                  int node) {
  return node_force_at(model, x, node, x[static_cast<std::size_t>(node)]);
}

/// Σ |l − L| over the springs at a node (m); a term no larger than the rounding of l counts as 0.
double deformation_sum(const Model& model, const std::vector<Eigen::Vector3d>& x, int node);

/// Total stretch energy of the fabric (J).
double stretch_energy(const Model& model, const std::vector<Eigen::Vector3d>& x);

/// Per-node strain: the mean strain of the node's warp springs and of its weft springs.
struct NodeStrains {
  std::vector<double> warp;
  std::vector<double> weft;
};
NodeStrains node_strains(const Model& model, const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
