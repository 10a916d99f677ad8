#pragma once
// Draw-in, the figure a forming engineer reads off a clamped blank: how far each node of the
// fabric's edge moved inwards from where it started, in the blank's plane (x, y), along the
// inward normal of the flat fabric's edge there (a rectangle's side, the diagonal at a corner,
// a circle's radius). Negative where the edge was pushed outwards. A garment's panels have none.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

struct DrawIn {
  std::vector<double> per_node_m;  // NaN for nodes off the edge
  double max_m = 0.0;              // the largest over the edge (0 for a fabric without one)
  int max_node = -1;               // where it is attained
};

DrawIn draw_in(const Model& model, const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
