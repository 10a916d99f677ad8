#include "fabform/model/equilibrium.hpp"

#include <algorithm>
#include <limits>
#include <optional>

#include "fabform/model/model.hpp"

namespace fabform {

Eigen::Vector3d unbalanced_force(const Eigen::Vector3d& resultant, AxisMask locks,
                                 const Eigen::Vector3d* contact_normal, double friction) {
  const Eigen::Vector3d free = remove_locked(resultant, locks);
  if (!contact_normal || free.dot(*contact_normal) >= 0.0) return free;
  // Pressing on the body, the node may move only along free axes that keep it on the tangent
  // plane: remove the part along the normal's free-axis component.
  const Eigen::Vector3d normal_free = remove_locked(*contact_normal, locks);
  const double length2 = normal_free.squaredNorm();
  if (length2 == 0.0) return free;
  const Eigen::Vector3d tangential = free - (free.dot(normal_free) / length2) * normal_free;
  if (friction == 0.0) return tangential;
  const double held = friction * pressing_force(resultant, locks, *contact_normal);
  const double length = tangential.norm();
  return length <= held ? Eigen::Vector3d::Zero() : Eigen::Vector3d((1.0 - held / length) * tangential);
}

double pressing_force(const Eigen::Vector3d& resultant, AxisMask locks, const Eigen::Vector3d& normal) {
  if (locks == 0) return std::max(-resultant.dot(normal), 0.0);
  const Eigen::Vector3d normal_free = remove_locked(normal, locks);
  const double length2 = normal_free.squaredNorm();
  if (length2 == 0.0) return 0.0;
  return std::max(-remove_locked(resultant, locks).dot(normal_free) / length2, 0.0);
}

NearestSurface nearest_surface(const Model& model, const Eigen::Vector3d& p) {
  NearestSurface nearest;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const SurfacePoint s = model.bodies[b].closest(p);
    if (nearest.body < 0 || s.distance < nearest.point.distance) nearest = {s, static_cast<int>(b)};
  }
  return nearest;
}

namespace {

enum class Grip { none, sliding, stuck };

// A node pressed on a body slides when its tangential force reaches μ·λ to within e (on a
// frictionless body, always), and is stuck when friction holds it further inside the cone; a
// node that touches a body without pressing on it is neither.
Grip grip(const Eigen::Vector3d& r, AxisMask locks, const Eigen::Vector3d& normal, double friction,
          double tolerance_N) {
  const double pressing = pressing_force(r, locks, normal);
  if (pressing == 0.0) return Grip::none;
  const bool inside = unbalanced_force(r, locks, &normal).norm() < friction * pressing - tolerance_N;
  return inside ? Grip::stuck : Grip::sliding;
}

}  // namespace

EquilibriumReport measure_equilibrium(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                      double contact_tolerance_m, double tolerance_N) {
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
    const bool touching = nearest.body >= 0 && nearest.point.distance <= contact_tolerance_m;
    if (nearest.body >= 0)
      report.max_penetration_m = std::max(report.max_penetration_m, -nearest.point.signed_distance);
    const Eigen::Vector3d r = node_force(model, x, static_cast<int>(k));
    const double friction = touching ? model.bodies[static_cast<std::size_t>(nearest.body)].friction() : 0.0;
    report.residual_N[k] =
        unbalanced_force(r, model.locks[k], touching ? &nearest.point.normal : nullptr, friction).norm();
    report.contact[k] = touching ? 1 : 0;
    report.contact_nodes += touching ? 1 : 0;
    if (touching) {
      const Grip g = grip(r, model.locks[k], nearest.point.normal, friction, tolerance_N);
      report.sliding_nodes += g == Grip::sliding ? 1 : 0;
      report.stuck_nodes += g == Grip::stuck ? 1 : 0;
    }
    if (report.residual_N[k] > report.max_residual_N || report.worst_node < 0) {
      report.max_residual_N = report.residual_N[k];
      report.worst_node = static_cast<int>(k);
    }
  }
  report.spring_cuts = find_spring_cuts(model, x);
  return report;
}

}  // namespace fabform
