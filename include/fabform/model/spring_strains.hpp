#pragma once
// How far the fabric's springs are from their rest lengths: the deformations d_k that set seed
// 003's relaxation step (Eq. 4), and the warp and weft strains a run reports per node.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// Σ |l − L| over the springs at a node (m); a term no larger than the rounding of l counts as 0.
double deformation_sum(const Model& model, const std::vector<Eigen::Vector3d>& x, int node);

/// Per-node strain: the mean strain of the node's warp springs and of its weft springs.
struct NodeStrains {
  std::vector<double> warp;
  std::vector<double> weft;
};
NodeStrains node_strains(const Model& model, const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
