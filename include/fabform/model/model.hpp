#pragma once
// Everything a solver needs, in SI, validated: the fabric grid and its warp and weft tables,
// the per-node axis locks, the rigid bodies, the starting positions and the constant loads.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/grid.hpp"
#include "fabform/fabric/node_set.hpp"
#include "fabform/geometry/rigid_body.hpp"
#include "fabform/material/tension_table.hpp"

namespace fabform {

struct Model {
  FabricGrid grid;
  TensionTable warp;
  TensionTable weft;
  std::vector<AxisMask> locks;  // one per node
  std::vector<RigidBody> bodies;
  std::vector<Eigen::Vector3d> start;  // one per node
  std::vector<Eigen::Vector3d> loads = {};  // N, one per node (the fabric's weight); empty: none
  std::vector<std::string> modelled = {};   // each term of the model, said for result.json

  const TensionTable& table(Direction direction) const {
    return direction == Direction::warp ? warp : weft;
  }
  int node_count() const { return grid.node_count(); }
};

}  // namespace fabform
