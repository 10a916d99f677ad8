#include "fabform/model/self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "fabform/geometry/closest_point.hpp"
#include "fabform/geometry/point_grid.hpp"
#include "fabform/model/model.hpp"

namespace fabform {
namespace {

// Barycentric weights of q, a point of triangle abc; none for a triangle without area.
std::optional<std::array<double, 3>> weights_of(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                                const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d e0 = b - a, e1 = c - a, d = q - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = d.dot(e0), d21 = d.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  if (!(det > 1e-24 * d00 * d11)) return std::nullopt;
  const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
  return std::array<double, 3>{1.0 - v - w, v, w};
}

// The coefficients of δ's gradient over the pair's nodes: the node, then the triangle's corners.
std::array<double, 4> coefficients(const ProximityPair& p) {
  return {1.0, -p.weights[0], -p.weights[1], -p.weights[2]};
}

}  // namespace

SelfContact::SelfContact(const Fabric& fabric, const std::vector<int>& sewn, double thickness_m, double stiffness_N_m)
    : triangles_(face_triangles(fabric.faces())),
      sewn_(sewn),
      ring_(static_cast<std::size_t>(fabric.node_count())),
      thickness_(thickness_m),
      stiffness_(stiffness_N_m) {
  if (!(thickness_ > 0.0 && std::isfinite(thickness_))) throw std::invalid_argument("the fabric's thickness must be positive");
  if (!(stiffness_ > 0.0 && std::isfinite(stiffness_))) throw std::invalid_argument("self-contact's stiffness must be positive");
  for (int n = 0; n < fabric.node_count(); ++n) {
    std::vector<int>& ring = ring_[static_cast<std::size_t>(sewn_[static_cast<std::size_t>(n)])];
    ring.push_back(sewn_[static_cast<std::size_t>(n)]);
    for (const int f : fabric.faces_at(n)) {
      const Face& face = fabric.faces()[static_cast<std::size_t>(f)];
      for (int c = 0; c < face.corners; ++c)
        ring.push_back(sewn_[static_cast<std::size_t>(face.corner[static_cast<std::size_t>(c)])]);
    }
  }
  for (std::vector<int>& ring : ring_) {
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  }
}

bool SelfContact::excluded(int node, int triangle) const {
  const std::vector<int>& ring = ring_[static_cast<std::size_t>(sewn_[static_cast<std::size_t>(node)])];
  for (const int corner : triangles_[static_cast<std::size_t>(triangle)])
    if (std::binary_search(ring.begin(), ring.end(), sewn_[static_cast<std::size_t>(corner)])) return true;
  return false;
}

std::vector<ProximityPair> SelfContact::pairs(const Positions& x, double reach_m) const {
  const double reach = reach_m > 0.0 ? reach_m : thickness_;
  // A broken state (a NaN or infinity, which the solvers report) has no cubes to bin it in.
  if (!std::all_of(x.begin(), x.end(), [](const Eigen::Vector3d& p) { return p.allFinite(); })) return {};
  const auto at = [&](int n) -> const Eigen::Vector3d& { return x[static_cast<std::size_t>(n)]; };
  std::vector<Eigen::Vector3d> centre(triangles_.size());
  double radius = 0.0;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& [a, b, c] = triangles_[t];
    centre[t] = (at(a) + at(b) + at(c)) / 3.0;
    for (const int corner : triangles_[t]) radius = std::max(radius, (at(corner) - centre[t]).norm());
  }
  // Every node within `reach` of a triangle lies within its radius plus `reach` of its centre.
  const PointGrid grid(x, radius + reach);
  std::vector<ProximityPair> found;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& [a, b, c] = triangles_[t];
    for (const int node : grid.near(centre[t])) {
      if (excluded(node, static_cast<int>(t))) continue;
      const Eigen::Vector3d q = closest_point_on_triangle(at(node), at(a), at(b), at(c)).point;
      const double distance = (at(node) - q).norm();
      if (distance >= reach) continue;
      const auto w = weights_of(q, at(a), at(b), at(c));
      if (!w) continue;  // a collapsed triangle: its neighbours still hold the node off
      const Eigen::Vector3d normal = (at(b) - at(a)).cross(at(c) - at(a)).normalized();
      const Eigen::Vector3d direction = distance > 0.0 ? Eigen::Vector3d((at(node) - q) / distance) : normal;
      found.push_back({node, static_cast<int>(t), *w, direction, distance});
    }
  }
  std::sort(found.begin(), found.end(), [](const ProximityPair& l, const ProximityPair& r) {
    return l.node != r.node ? l.node < r.node : l.triangle < r.triangle;
  });
  return found;
}

double SelfContact::penalty(double distance) const {
  const double gap = thickness_ - distance;
  return gap > 0.0 ? stiffness_ * gap * gap * gap / (3.0 * thickness_) : 0.0;
}

double SelfContact::penalty_slope(double distance) const {
  const double gap = thickness_ - distance;
  return gap > 0.0 ? -stiffness_ * gap * gap / thickness_ : 0.0;
}

double SelfContact::penalty_curvature(double distance) const {
  const double gap = thickness_ - distance;
  return gap > 0.0 ? 2.0 * stiffness_ * gap / thickness_ : 0.0;
}

std::string SelfContact::describe(const Model& /*model*/) const {
  char text[240];
  std::snprintf(text, sizeof text,
                "self-contact: a node closer than the thickness %.4g m to a triangle of the fabric is pushed off it, "
                "penalty kappa (d - delta)^3 / (3 d), kappa = %.6g N/m (%zu triangles)",
                thickness_, stiffness_, triangles_.size());
  return text;
}

void SelfContact::add_forces(const Model& /*model*/, const Positions& x, std::vector<Eigen::Vector3d>& forces) const {
  for (const ProximityPair& p : pairs(x)) {
    const std::array<double, 4> c = coefficients(p);
    const auto& tri = triangles_[static_cast<std::size_t>(p.triangle)];
    const std::array<int, 4> nodes = {p.node, tri[0], tri[1], tri[2]};
    const double slope = penalty_slope(p.distance_m);
    for (std::size_t i = 0; i < 4; ++i) forces[static_cast<std::size_t>(nodes[i])] -= slope * c[i] * p.direction;
  }
}

Eigen::Vector3d SelfContact::force_at(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const {
  Positions moved = x;
  moved[static_cast<std::size_t>(node)] = at;
  std::vector<Eigen::Vector3d> forces(x.size(), Eigen::Vector3d::Zero());
  add_forces(model, moved, forces);
  return forces[static_cast<std::size_t>(node)];
}

double SelfContact::energy(const Model& /*model*/, const Positions& x) const {
  double energy = 0.0;
  for (const ProximityPair& p : pairs(x)) energy += penalty(p.distance_m);
  return energy;
}

double SelfContact::node_energy_change(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const {
  Positions moved = x;
  moved[static_cast<std::size_t>(node)] = at;
  return energy(model, moved) - energy(model, x);
}

void SelfContact::add_stiffness(const Model& /*model*/, const Positions& x, StiffnessSink& sink) const {
  for (const ProximityPair& p : pairs(x)) {
    const std::array<double, 4> c = coefficients(p);
    const auto& tri = triangles_[static_cast<std::size_t>(p.triangle)];
    const std::array<int, 4> nodes = {p.node, tri[0], tri[1], tri[2]};
    const Eigen::Matrix3d block = penalty_curvature(p.distance_m) * p.direction * p.direction.transpose();
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i; j < 4; ++j) sink.add(nodes[i], nodes[j], c[i] * c[j] * block);
  }
}

double self_contact_stiffness_N_m(const Model& model) {
  return kSelfContactRatio * std::max(model.warp.steepest_slope(), model.weft.steepest_slope());
}

}  // namespace fabform
