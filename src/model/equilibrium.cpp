#include "fabform/model/equilibrium.hpp"

#include <algorithm>
#include <limits>
#include <optional>

#include "fabform/model/model.hpp"

namespace fabform {

Eigen::Vector3d unbalanced_force(const Eigen::Vector3d& resultant, AxisMask locks,
                                 const Eigen::Vector3d* contact_normal) {
  const Eigen::Vector3d free = remove_locked(resultant, locks);
  if (!contact_normal || free.dot(*contact_normal) >= 0.0) return free;
  // Pressing on the body, the node may move only along free axes that keep it on the tangent
  // plane: remove the part along the normal's free-axis component.
  const Eigen::Vector3d normal_free = remove_locked(*contact_normal, locks);
  const double length2 = normal_free.squaredNorm();
  if (length2 == 0.0) return free;
  return free - (free.dot(normal_free) / length2) * normal_free;
}

namespace {

struct NearestSurface {
  SurfacePoint point;
  bool found = false;
};

NearestSurface nearest_surface(const Model& model, const Eigen::Vector3d& p) {
  NearestSurface nearest;
  for (const RigidBody& body : model.bodies) {
    const SurfacePoint s = body.closest(p);
    if (!nearest.found || s.distance < nearest.point.distance) nearest = {s, true};
  }
  return nearest;
}

}  // namespace

EquilibriumReport measure_equilibrium(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                      double contact_tolerance_m) {
  const auto n = static_cast<std::size_t>(model.node_count());
  EquilibriumReport report;
  report.residual_N.assign(n, 0.0);
  report.contact.assign(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    if (!x[k].allFinite()) {  // no geometry query on a broken state: report it and stop
      report.max_residual_N = std::numeric_limits<double>::quiet_NaN();
      report.worst_node = static_cast<int>(k);
      return report;
    }
    const NearestSurface nearest = nearest_surface(model, x[k]);
    const bool touching = nearest.found && nearest.point.distance <= contact_tolerance_m;
    if (nearest.found)
      report.max_penetration_m = std::max(report.max_penetration_m, -nearest.point.signed_distance);
    const Eigen::Vector3d r = node_force(model, x, static_cast<int>(k));
    report.residual_N[k] =
        unbalanced_force(r, model.locks[k], touching ? &nearest.point.normal : nullptr).norm();
    report.contact[k] = touching ? 1 : 0;
    report.contact_nodes += touching ? 1 : 0;
    if (report.residual_N[k] > report.max_residual_N || report.worst_node < 0) {
      report.max_residual_N = report.residual_N[k];
      report.worst_node = static_cast<int>(k);
    }
  }
  return report;
}

}  // namespace fabform
