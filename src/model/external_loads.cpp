#include "fabform/model/external_loads.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <limits>

namespace fabform {

std::vector<Eigen::Vector3d> gravity_loads(const Fabric& grid, double areal_density_kg_m2,
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

double load_energy_change(const std::vector<Eigen::Vector3d>& loads, const std::vector<Eigen::Vector3d>& from,
                          const std::vector<Eigen::Vector3d>& to) {
  double change = 0.0;
  for (std::size_t k = 0; k < loads.size(); ++k) change -= loads[k].dot(to[k] - from[k]);
  return change;
}

std::string load_tolerance_warning(const std::vector<Eigen::Vector3d>& loads, double tolerance_N) {
  if (loads.empty()) return "";
  double lightest = std::numeric_limits<double>::infinity();
  for (const auto& f : loads) lightest = std::min(lightest, f.norm());
  if (tolerance_N < 0.1 * lightest) return "";
  char text[240];
  std::snprintf(text, sizeof text,
                "e = %.3g N is %.3g times the lightest node's weight (%.3g N): the run can stop before "
                "the weight has taken effect; choose e below %.2g N",
                tolerance_N, tolerance_N / lightest, lightest, 0.01 * lightest);
  return text;
}

}  // namespace fabform
