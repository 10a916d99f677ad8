#pragma once
// A fabric's flat positions, and a model of it with linear 500 N/m tables and no node held: what
// the term tests bend, shear and perturb.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform::test {

inline Positions flat_positions(const Fabric& fabric) {
  Positions x;
  for (int k = 0; k < fabric.node_count(); ++k) x.push_back(fabric.rest_position(k));
  return x;
}

inline Model free_model(const Fabric& fabric) {
  const TensionTable table({{0, 0}, {1, 500}}, "t");
  return Model{fabric, table, table, std::vector<AxisMask>(static_cast<std::size_t>(fabric.node_count()), 0), {}, {}};
}

}  // namespace fabform::test
