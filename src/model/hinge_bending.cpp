#include "fabform/model/hinge_bending.hpp"

#include <algorithm>
#include <cmath>

namespace fabform {
namespace {

// A face whose far point lies within this fraction of the edge's length from the edge's line
// has collapsed: it has no normal, so no angle and no bending.
constexpr double kCollapsed = 1e-12;

struct Frame {
  Eigen::Vector3d axis;          // ê, along the edge
  Eigen::Vector3d across[2];     // each far point's offset from the edge's line (d₁, d₂)
  double along[2] = {0.0, 0.0};  // where each far point projects on the edge: 0 at p0, 1 at p1
  bool collapsed = true;
};

Frame frame_of(const std::array<Eigen::Vector3d, 4>& p) {
  Frame f;
  const Eigen::Vector3d e = p[1] - p[0];
  const double length = e.norm();
  if (!(length > 0.0)) return f;
  f.axis = e / length;
  for (int w = 0; w < 2; ++w) {
    const Eigen::Vector3d r = p[static_cast<std::size_t>(2 + w)] - p[0];
    const double t = r.dot(f.axis);
    f.across[w] = r - t * f.axis;
    f.along[w] = t / length;
    if (!(f.across[w].norm() > kCollapsed * length)) return f;
  }
  f.collapsed = false;
  return f;
}

}  // namespace

std::array<Eigen::Vector3d, 4> hinge_points(const Hinge& hinge, const std::vector<Eigen::Vector3d>& x, int moved,
                                            const Eigen::Vector3d& at) {
  const auto p = [&](int node) { return node == moved ? at : x[static_cast<std::size_t>(node)]; };
  return {p(hinge.edge[0]), p(hinge.edge[1]), 0.5 * (p(hinge.wing[0][0]) + p(hinge.wing[0][1])),
          0.5 * (p(hinge.wing[1][0]) + p(hinge.wing[1][1]))};
}

// θ turns d₁ onto −d₂ about ê: 0 when the faces lie flat, on either side of the edge.
double dihedral_angle(const std::array<Eigen::Vector3d, 4>& p) {
  const Frame f = frame_of(p);
  if (f.collapsed) return 0.0;
  return std::atan2(-f.axis.dot(f.across[0].cross(f.across[1])), -f.across[0].dot(f.across[1]));
}

// Moving a far point along its face's normal ê × d̂ by δ turns its face by δ/|d| about the
// edge; the edge's nodes take the rest in proportion to where each far point projects, so that
// the angle stays put under translation and rotation (Bridson et al. 2003).
std::array<Eigen::Vector3d, 4> dihedral_angle_gradient(const std::array<Eigen::Vector3d, 4>& p) {
  const Frame f = frame_of(p);
  std::array<Eigen::Vector3d, 4> g;
  for (auto& v : g) v.setZero();
  if (f.collapsed) return g;
  const auto turn = [&](int w) {
    const Eigen::Vector3d& d = f.across[w];
    return Eigen::Vector3d(f.axis.cross(d) / d.squaredNorm());
  };
  g[2] = -turn(0);
  g[3] = turn(1);
  g[0] = -(1.0 - f.along[0]) * g[2] - (1.0 - f.along[1]) * g[3];
  g[1] = -f.along[0] * g[2] - f.along[1] * g[3];
  return g;
}

double hinge_energy(const Hinge& hinge, double rigidity_Nm, const std::vector<Eigen::Vector3d>& x, int moved,
                    const Eigen::Vector3d& at) {
  const double theta = dihedral_angle(hinge_points(hinge, x, moved, at));
  return 2.0 * rigidity_Nm * hinge.shape_factor * (1.0 - std::cos(theta));
}

HingeGradient hinge_gradient(const Hinge& hinge, const std::vector<Eigen::Vector3d>& x, int moved,
                             const Eigen::Vector3d& at) {
  const std::array<Eigen::Vector3d, 4> p = hinge_points(hinge, x, moved, at);
  const std::array<Eigen::Vector3d, 4> g = dihedral_angle_gradient(p);
  HingeGradient out;
  out.theta = dihedral_angle(p);
  const auto add = [&](int node, const Eigen::Vector3d& d) {
    for (int k = 0; k < out.count; ++k)
      if (out.node[static_cast<std::size_t>(k)] == node) {
        out.d_theta[static_cast<std::size_t>(k)] += d;
        return;
      }
    out.node[static_cast<std::size_t>(out.count)] = node;
    out.d_theta[static_cast<std::size_t>(out.count)] = d;
    ++out.count;
  };
  add(hinge.edge[0], g[0]);
  add(hinge.edge[1], g[1]);
  for (int w = 0; w < 2; ++w)
    for (const int node : hinge.wing[static_cast<std::size_t>(w)]) add(node, 0.5 * g[static_cast<std::size_t>(2 + w)]);
  return out;
}

double bending_energy(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  if (!model.bending_rigidity_Nm) return 0.0;
  double energy = 0.0;
  for (const Hinge& h : model.fabric.hinges()) energy += hinge_energy(h, *model.bending_rigidity_Nm, x);
  return energy;
}

Eigen::Vector3d bending_force_at(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                                 const Eigen::Vector3d& at) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  if (!model.bending_rigidity_Nm) return force;
  for (const int i : model.fabric.hinges_at(node)) {
    const Hinge& h = model.fabric.hinges()[static_cast<std::size_t>(i)];
    const HingeGradient g = hinge_gradient(h, x, node, at);
    if (g.theta == 0.0) continue;
    const auto k = static_cast<std::size_t>(std::find(g.node.begin(), g.node.begin() + g.count, node) - g.node.begin());
    force -= 2.0 * *model.bending_rigidity_Nm * h.shape_factor * std::sin(g.theta) * g.d_theta[k];
  }
  return force;
}

double node_bending_energy(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                           const Eigen::Vector3d& at) {
  if (!model.bending_rigidity_Nm) return 0.0;
  double energy = 0.0;
  for (const int i : model.fabric.hinges_at(node))
    energy += hinge_energy(model.fabric.hinges()[static_cast<std::size_t>(i)], *model.bending_rigidity_Nm, x, node, at);
  return energy;
}

}  // namespace fabform
