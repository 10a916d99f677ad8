#include "fabform/model/gravity.hpp"

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

Gravity::Gravity(const Fabric& fabric, double areal_density_kg_m2, double acceleration_m_s2)
    : loads_(gravity_loads(fabric, areal_density_kg_m2, acceleration_m_s2)),
      areal_density_kg_m2_(areal_density_kg_m2),
      acceleration_m_s2_(acceleration_m_s2) {}

std::string Gravity::describe(const Model& /*model*/) const {
  char text[160];
  std::snprintf(text, sizeof text,
                "gravity: %.6g m/s² along -z on an areal density of %.6g kg/m² (material files)",
                acceleration_m_s2_, areal_density_kg_m2_);
  return text;
}

Eigen::Vector3d Gravity::force_at(const Model& /*model*/, const Positions& /*x*/, int node,
                                  const Eigen::Vector3d& /*at*/) const {
  return loads_[static_cast<std::size_t>(node)];
}

double Gravity::energy(const Model& /*model*/, const Positions& x) const {
  double energy = 0.0;
  for (std::size_t k = 0; k < loads_.size(); ++k) energy -= loads_[k].dot(x[k]);
  return energy;
}

double Gravity::energy_change(const Model& /*model*/, const Positions& from, double /*from_energy*/,
                              const Positions& to) const {
  double change = 0.0;
  for (std::size_t k = 0; k < loads_.size(); ++k) change -= loads_[k].dot(to[k] - from[k]);
  return change;
}

double Gravity::node_energy_change(const Model& /*model*/, const Positions& x, int node,
                                   const Eigen::Vector3d& at) const {
  const auto k = static_cast<std::size_t>(node);
  return -loads_[k].dot(at - x[k]);
}

std::string Gravity::tolerance_warning(double tolerance_N) const {
  double lightest = std::numeric_limits<double>::infinity();
  for (const auto& f : loads_) lightest = std::min(lightest, f.norm());
  if (loads_.empty() || tolerance_N < 0.1 * lightest) return "";
  char text[240];
  std::snprintf(text, sizeof text,
                "e = %.3g N is %.3g times the lightest node's weight (%.3g N): the run can stop before "
                "the weight has taken effect; choose e below %.2g N",
                tolerance_N, tolerance_N / lightest, lightest, 0.01 * lightest);
  return text;
}

}  // namespace fabform
