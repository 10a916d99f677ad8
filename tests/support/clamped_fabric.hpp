#pragma once
// The solvers' common small problem: a 10 × 10 cm fabric of a linear material, perimeter
// locked in every axis, optionally stretched in its plane and lifted in its middle.
#include <vector>

#include "fabform/model/model.hpp"

namespace fabform::test {

inline TensionTable linear_table(double stiffness_N_per_m) {
  return TensionTable({{0.0, 0.0}, {1.0, stiffness_N_per_m}}, "linear");
}

// Stretched in its plane by `prestretch`: a clamped membrane needs tension to resist moving
// out of plane.
inline Model clamped_fabric(int divisions, double prestretch = 0.0) {
  Fabric grid({0.1, 0.1, divisions, divisions});
  std::vector<AxisMask> locks(static_cast<std::size_t>(grid.node_count()), 0);
  std::vector<Eigen::Vector3d> x(static_cast<std::size_t>(grid.node_count()));
  const Eigen::Vector3d centre(0.05, 0.05, 0.0);
  for (int k = 0; k < grid.node_count(); ++k) {
    x[static_cast<std::size_t>(k)] = centre + (1.0 + prestretch) * (grid.rest_position(k) - centre);
    if (grid.on_perimeter(k)) locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
  }
  return Model{grid, linear_table(500.0), linear_table(500.0), locks, {}, x};
}

inline void lift_interior(Model& model, double height) {
  for (int k = 0; k < model.node_count(); ++k)
    if (!model.fabric.on_perimeter(k)) model.start[static_cast<std::size_t>(k)].z() = height;
}

}  // namespace fabform::test
