#include "fabform/model/external_loads.hpp"

#include <cstddef>

namespace fabform {

std::vector<Eigen::Vector3d> gravity_loads(const FabricGrid& grid, double areal_density_kg_m2,
                                           double acceleration_m_s2) {
  const std::vector<double> area = grid.node_areas();
  std::vector<Eigen::Vector3d> loads(area.size());
  for (std::size_t k = 0; k < area.size(); ++k)
    loads[k] = Eigen::Vector3d(0.0, 0.0, -areal_density_kg_m2 * area[k] * acceleration_m_s2);
  return loads;
}

double load_energy(const std::vector<Eigen::Vector3d>& loads, const std::vector<Eigen::Vector3d>& x) {
  double energy = 0.0;
  for (std::size_t k = 0; k < loads.size(); ++k) energy -= loads[k].dot(x[k]);
  return energy;
}

}  // namespace fabform
