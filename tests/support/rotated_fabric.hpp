#pragma once
// A fabric laid out at rest, turned about z and moved off the origin, so that its springs'
// lengths, computed from the coordinates, differ from their rest lengths by rounding alone.
#include <vector>

#include <Eigen/Geometry>

#include "support/clamped_fabric.hpp"

namespace fabform::test {

// Corners locked in every axis; every other node free.
inline Model rotated_fabric_at_rest(int divisions) {
  Fabric grid({0.1, 0.1, divisions, divisions});
  const Eigen::AngleAxisd turn(0.3, Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d offset(0.123456789, -0.0654321, 0.002);
  std::vector<AxisMask> locks(static_cast<std::size_t>(grid.node_count()), 0);
  std::vector<Eigen::Vector3d> x(static_cast<std::size_t>(grid.node_count()));
  for (int k = 0; k < grid.node_count(); ++k) {
    x[static_cast<std::size_t>(k)] = offset + turn * grid.rest_position(k);
    const bool corner = (grid.i_of(k) == 0 || grid.i_of(k) == divisions) &&
                        (grid.j_of(k) == 0 || grid.j_of(k) == divisions);
    if (corner) locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
  }
  return Model{grid, linear_table(500.0), linear_table(500.0), locks, {}, x};
}

}  // namespace fabform::test
