#include "fabform/analysis/contact_pressure.hpp"

#include <algorithm>

#include "fabform/geometry/point_grid.hpp"
#include "fabform/model/equilibrium.hpp"
#include "fabform/model/seam.hpp"
#include "fabform/model/spring_path.hpp"
#include "fabform/model/wrapped_spring.hpp"

namespace fabform {
namespace {

// Each node's share of the formed fabric's area.
std::vector<double> tributary_areas(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x) {
  std::vector<double> area(x.size(), 0.0);
  for (const Face& face : fabric.faces()) {
    const double share = face_area(face, x) / face.corners;
    for (int c = 0; c < face.corners; ++c) area[static_cast<std::size_t>(face.corner[static_cast<std::size_t>(c)])] += share;
  }
  return area;
}

// The body's reaction on a node it touches: the nearest body's normal decides the direction, or
// on a crease its two faces' normals.
double reaction_N(const Model& model, const std::vector<Eigen::Vector3d>& x, const Eigen::Vector3d& force, int node,
                  NearbyQueries& queries) {
  const auto k = static_cast<std::size_t>(node);
  const NearestSurface nearest = nearest_surface(model, queries, x[k]);
  if (nearest.body < 0) return 0.0;
  const SurfaceSupport support = surface_support(model, nearest, model.locks[k]);
  return pressing_force(force, model.locks[k], support.normal, support.crease_normal());
}

// The force with which the springs wrapped over the bodies' edges press on them, half on each
// end's node: a string of tension f over an edge pulls it by f·(u_a + u_b), the unit legs to its
// nodes, and the edge pushes back as much.
std::vector<double> edge_forces_N(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  std::vector<double> force(x.size(), 0.0);
  if (!model.wraps_edges()) return force;
  for (const Spring& s : model.fabric.springs()) {
    const Eigen::Vector3d& a = x[static_cast<std::size_t>(s.a)];
    const Eigen::Vector3d& b = x[static_cast<std::size_t>(s.b)];
    const std::optional<EdgeWrap> wrap = spring_wrap(model, s, a, b);
    if (!wrap) continue;
    const double tension = wrapped_spring_force(a, *wrap, s, model.table(s.kind)).norm();
    const double pressing = tension * ((a - wrap->point).normalized() + (b - wrap->point).normalized()).norm();
    force[static_cast<std::size_t>(s.a)] += 0.5 * pressing;
    force[static_cast<std::size_t>(s.b)] += 0.5 * pressing;
  }
  return force;
}

// How far a node's pressure reaches over a body: its longest warp or weft side as formed.
double reach_m(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x, int node) {
  double reach = 0.0;
  for (const int s : fabric.springs_at(node)) {
    const Spring& spring = fabric.springs()[static_cast<std::size_t>(s)];
    if (spring.kind <= SpringKind::weft)
      reach = std::max(reach, (x[static_cast<std::size_t>(spring.a)] - x[static_cast<std::size_t>(spring.b)]).norm());
  }
  return reach;
}

// Each vertex takes the pressure of the nearest pressing node within that node's reach (the
// first such node where several are as near).
std::vector<double> vertex_pressure(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& x,
                                    const std::vector<int>& pressing, const std::vector<double>& reach,
                                    const std::vector<double>& node_Pa) {
  std::vector<Eigen::Vector3d> at(pressing.size());
  for (std::size_t n = 0; n < pressing.size(); ++n) at[n] = x[static_cast<std::size_t>(pressing[n])];
  const PointGrid grid(at, reach.empty() ? 0.0 : *std::max_element(reach.begin(), reach.end()));
  std::vector<double> pressure(mesh.vertices.size(), 0.0);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    double nearest = -1.0;
    for (const int n : grid.near(mesh.vertices[v])) {
      const auto i = static_cast<std::size_t>(n);
      const double d = (mesh.vertices[v] - at[i]).norm();
      if (d <= reach[i] && (nearest < 0.0 || d < nearest))
        nearest = d, pressure[v] = node_Pa[static_cast<std::size_t>(pressing[i])];
    }
  }
  return pressure;
}

}  // namespace

ContactPressure contact_pressure(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                 const std::vector<unsigned char>& contact) {
  ContactPressure p;
  p.node_Pa.assign(x.size(), 0.0);
  const std::vector<double> area = tributary_areas(model.fabric, x);
  const std::vector<double> over_edges = edge_forces_N(model, x);
  double force = 0.0, contact_area = 0.0;
  std::vector<int> pressing;
  std::vector<double> reach;
  NearbyQueries queries(model.bodies);
  // Nodes sewn onto one another are one point of the garment: they press with their reactions
  // together over their areas together (how the seam's stitches share the reaction between them
  // is the stitches' business, not the body's).
  const std::vector<int> sewn = sewn_representatives(model);
  const std::vector<Eigen::Vector3d> forces = node_forces(model, x);
  std::vector<double> lambda(x.size(), 0.0), sewn_lambda(x.size(), 0.0), sewn_area(x.size(), 0.0);
  const auto presses = [&](std::size_t i) { return (contact[i] || over_edges[i] != 0.0) && area[i] > 0.0; };
  for (int k = 0; k < model.node_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (!presses(i)) continue;
    lambda[i] = (contact[i] ? reaction_N(model, x, forces[i], k, queries) : 0.0) + over_edges[i];
    sewn_lambda[static_cast<std::size_t>(sewn[i])] += lambda[i];
    sewn_area[static_cast<std::size_t>(sewn[i])] += area[i];
  }
  for (int k = 0; k < model.node_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (!presses(i)) continue;
    const auto group = static_cast<std::size_t>(sewn[i]);
    p.node_Pa[i] = sewn_lambda[group] / sewn_area[group];
    if (lambda[i] > 0.0) force += lambda[i], contact_area += area[i];  // the mean is over the area that presses
    if (p.max_node < 0 || p.node_Pa[i] > p.max_Pa) p.max_Pa = p.node_Pa[i], p.max_node = k;
    if (lambda[i] > 0.0) pressing.push_back(k), reach.push_back(reach_m(model.fabric, x, k));
  }
  p.mean_Pa = contact_area > 0.0 ? force / contact_area : 0.0;
  for (const RigidBody& body : model.bodies)
    p.body_vertex_Pa.push_back(vertex_pressure(body.posed_mesh(), x, pressing, reach, p.node_Pa));
  return p;
}

}  // namespace fabform
