#include "fabform/model/equilibrium.hpp"

#include <algorithm>
#include <limits>
#include <optional>

#include "fabform/model/model.hpp"

namespace fabform {

namespace {

// R = a n₁ + b n₂ + γ t: its parts along two unit normals that differ (valley_normals keeps them
// kCreaseAngleDeg apart, so the 2 × 2 system is well conditioned).
Eigen::Vector2d crease_parts(const Eigen::Vector3d& r, const Eigen::Vector3d& first, const Eigen::Vector3d& second) {
  const double c = first.dot(second);
  const double along_first = r.dot(first), along_second = r.dot(second);
  return Eigen::Vector2d(along_first - c * along_second, along_second - c * along_first) / (1.0 - c * c);
}

// The one-normal rule: a node pressing on a face keeps R's part within its tangent plane.
Eigen::Vector3d unbalanced_on_face(const Eigen::Vector3d& resultant, AxisMask locks, const Eigen::Vector3d& normal,
                                   double friction) {
  const Eigen::Vector3d free = remove_locked(resultant, locks);
  if (free.dot(normal) >= 0.0) return free;
  // Pressing on the body, the node may move only along free axes that keep it on the tangent
  // plane: remove the part along the normal's free-axis component.
  const Eigen::Vector3d normal_free = remove_locked(normal, locks);
  const double length2 = normal_free.squaredNorm();
  if (length2 == 0.0) return free;
  const Eigen::Vector3d tangential = free - (free.dot(normal_free) / length2) * normal_free;
  if (friction == 0.0) return tangential;
  const double held = friction * pressing_force(resultant, locks, normal);
  const double length = tangential.norm();
  return length <= held ? Eigen::Vector3d::Zero() : Eigen::Vector3d((1.0 - held / length) * tangential);
}

}  // namespace

CreaseHold crease_hold(const Eigen::Vector3d& resultant, const Eigen::Vector3d& first, const Eigen::Vector3d& second) {
  const Eigen::Vector2d parts = crease_parts(resultant, first, second);
  if (parts[0] <= 0.0 && parts[1] <= 0.0) return CreaseHold::both;
  if (parts[0] <= 0.0) return resultant.dot(first) < 0.0 ? CreaseHold::first : CreaseHold::none;
  if (parts[1] <= 0.0) return resultant.dot(second) < 0.0 ? CreaseHold::second : CreaseHold::none;
  return CreaseHold::none;
}

Eigen::Vector3d unbalanced_force(const Eigen::Vector3d& resultant, AxisMask locks,
                                 const Eigen::Vector3d* contact_normal, double friction, const Eigen::Vector3d* crease) {
  if (!contact_normal) return remove_locked(resultant, locks);
  if (!crease || locks != 0) return unbalanced_on_face(resultant, locks, *contact_normal, friction);
  switch (crease_hold(resultant, *contact_normal, *crease)) {
    case CreaseHold::first: return unbalanced_on_face(resultant, locks, *contact_normal, friction);
    case CreaseHold::second: return unbalanced_on_face(resultant, locks, *crease, friction);
    case CreaseHold::none: return resultant;
    case CreaseHold::both: break;
  }
  const Eigen::Vector2d parts = crease_parts(resultant, *contact_normal, *crease);
  const Eigen::Vector3d reaction = parts[0] * *contact_normal + parts[1] * *crease;
  const Eigen::Vector3d along = resultant - reaction;
  const double held = friction * reaction.norm();
  const double length = along.norm();
  return length <= held ? Eigen::Vector3d::Zero() : Eigen::Vector3d((1.0 - held / length) * along);
}

double pressing_force(const Eigen::Vector3d& resultant, AxisMask locks, const Eigen::Vector3d& normal,
                      const Eigen::Vector3d* crease) {
  if (crease && locks == 0) {
    switch (crease_hold(resultant, normal, *crease)) {
      case CreaseHold::both: {
        const Eigen::Vector2d parts = crease_parts(resultant, normal, *crease);
        return (parts[0] * normal + parts[1] * *crease).norm();
      }
      case CreaseHold::second: return pressing_force(resultant, locks, *crease);
      case CreaseHold::first:
      case CreaseHold::none: break;
    }
  }
  if (locks == 0) return std::max(-resultant.dot(normal), 0.0);
  const Eigen::Vector3d normal_free = remove_locked(normal, locks);
  const double length2 = normal_free.squaredNorm();
  if (length2 == 0.0) return 0.0;
  return std::max(-remove_locked(resultant, locks).dot(normal_free) / length2, 0.0);
}

NearestSurface nearest_surface(const Model& model, NearbyQueries& queries, const Eigen::Vector3d& p) {
  NearestSurface nearest;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const SurfacePoint s = queries.closest(static_cast<int>(b), p);
    if (nearest.body < 0 || s.distance < nearest.point.distance) nearest = {s, static_cast<int>(b)};
  }
  return nearest;
}

SurfaceSupport surface_support(const Model& model, const NearestSurface& nearest, AxisMask locks) {
  const RigidBody& body = model.bodies[static_cast<std::size_t>(nearest.body)];
  const auto faces = locks == 0 ? body.valley_normals(nearest.point.point) : std::nullopt;
  if (!faces) return {nearest.point.normal, std::nullopt};
  return {(*faces)[0], (*faces)[1]};
}

namespace {

enum class Grip { none, sliding, stuck };

// A node pressed on a body slides when its tangential force reaches μ·λ to within e (on a
// frictionless body, always), and is stuck when friction holds it further inside the cone; a
// node that touches a body without pressing on it is neither.
Grip grip(const Eigen::Vector3d& r, AxisMask locks, const Eigen::Vector3d& normal, const Eigen::Vector3d* crease,
          double friction, double tolerance_N) {
  const double pressing = pressing_force(r, locks, normal, crease);
  if (pressing == 0.0) return Grip::none;
  const bool inside = unbalanced_force(r, locks, &normal, 0.0, crease).norm() < friction * pressing - tolerance_N;
  return inside ? Grip::stuck : Grip::sliding;
}

// What the check finds at one node, computed on its own so that nodes can be measured in
// parallel and summed in their order.
struct NodeCheck {
  double penetration_m = -std::numeric_limits<double>::infinity();  // none without a body
  bool penetration_bounded = false;  // penetration_m is only an upper bound
  double residual_N = 0.0;
  bool touching = false;
  Grip grip = Grip::none;
};

// How far outside every body p lies at least, as `queries` prove without asking (−∞ where they
// do not prove it for some body, or there is none).
double least_clearance(const Model& model, const NearbyQueries& queries, const Eigen::Vector3d& p) {
  double least = model.bodies.empty() ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) least = std::min(least, queries.clearance_bound(static_cast<int>(b), p));
  return least;
}

NodeCheck check_node(const Model& model, const std::vector<Eigen::Vector3d>& x, const Eigen::Vector3d& r, int node,
                     NearbyQueries& queries, double contact_tolerance_m, double tolerance_N) {
  const auto k = static_cast<std::size_t>(node);
  NodeCheck c;
  NearestSurface nearest;
  // A node proved clear of every body touches none, and is no deeper in one than the bound says.
  if (const double clear = least_clearance(model, queries, x[k]); clear > contact_tolerance_m) {
    c.penetration_m = -clear;
    c.penetration_bounded = true;
  } else {
    nearest = nearest_surface(model, queries, x[k]);
  }
  c.touching = nearest.body >= 0 && nearest.point.distance <= contact_tolerance_m;
  if (nearest.body >= 0) c.penetration_m = -nearest.point.signed_distance;
  if (!c.touching) {
    c.residual_N = remove_locked(r, model.locks[k]).norm();
    return c;
  }
  const double friction = model.bodies[static_cast<std::size_t>(nearest.body)].friction();
  // In a valley both its faces hold the node, as newton holds it there (NodeContact::crease).
  const SurfaceSupport support = surface_support(model, nearest, model.locks[k]);
  c.residual_N = unbalanced_force(r, model.locks[k], &support.normal, friction, support.crease_normal()).norm();
  c.grip = grip(r, model.locks[k], support.normal, support.crease_normal(), friction, tolerance_N);
  return c;
}

// The deepest penetration of any node: the measured ones', and a bounded node's measured where
// its bound could exceed that (deepest bound first, so most are settled by the bound).
double deepest_penetration(const Model& model, const std::vector<Eigen::Vector3d>& x, const std::vector<NodeCheck>& checks) {
  double deepest = -std::numeric_limits<double>::infinity();
  std::vector<int> bounded;
  for (std::size_t k = 0; k < checks.size(); ++k) {
    if (checks[k].penetration_bounded) bounded.push_back(static_cast<int>(k));
    else deepest = std::max(deepest, checks[k].penetration_m);
  }
  const auto bound = [&](int k) { return checks[static_cast<std::size_t>(k)].penetration_m; };
  std::sort(bounded.begin(), bounded.end(), [&](int a, int b) { return bound(a) > bound(b); });
  NearbyQueries queries(model.bodies);
  for (const int k : bounded) {
    if (bound(k) <= deepest) break;
    deepest = std::max(deepest, -nearest_surface(model, queries, x[static_cast<std::size_t>(k)]).point.signed_distance);
  }
  return deepest;
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
  }
  std::vector<NodeCheck> checks(n);
  const std::vector<Eigen::Vector3d> forces = node_forces(model, x);
  for_each_nearby(model.node_count(), model.bodies, [&](int k, NearbyQueries& queries) {
    checks[static_cast<std::size_t>(k)] =
        check_node(model, x, forces[static_cast<std::size_t>(k)], k, queries, contact_tolerance_m, tolerance_N);
  });
  report.max_penetration_m = deepest_penetration(model, x, checks);
  for (std::size_t k = 0; k < n; ++k) {
    const NodeCheck& c = checks[k];
    report.residual_N[k] = c.residual_N;
    report.contact[k] = c.touching ? 1 : 0;
    report.contact_nodes += c.touching ? 1 : 0;
    report.sliding_nodes += c.grip == Grip::sliding ? 1 : 0;
    report.stuck_nodes += c.grip == Grip::stuck ? 1 : 0;
    if (report.residual_N[k] > report.max_residual_N || report.worst_node < 0) {
      report.max_residual_N = report.residual_N[k];
      report.worst_node = static_cast<int>(k);
    }
  }
  report.spring_cuts = find_spring_cuts(model, x);
  return report;
}

}  // namespace fabform
