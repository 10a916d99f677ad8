#include "fabform/fabric/node_set.hpp"

#include <algorithm>
#include <limits>

namespace fabform {

bool parse_named_node_set(const std::string& name, NodeSetSpec* spec) {
  using Kind = NodeSetSpec::Kind;
  static const std::pair<const char*, Kind> kNames[] = {
      {"perimeter", Kind::perimeter},     {"corners", Kind::corners},
      {"edge:left", Kind::edge_left},     {"edge:right", Kind::edge_right},
      {"edge:bottom", Kind::edge_bottom}, {"edge:top", Kind::edge_top}};
  for (const auto& [text, kind] : kNames)
    if (name == text) {
      spec->kind = kind;
      return true;
    }
  return false;
}

namespace {

// Edges and corners are a rectangle's: a circle has none.
bool in_named_set(const Fabric& fabric, NodeSetSpec::Kind kind, int node) {
  using Kind = NodeSetSpec::Kind;
  if (kind == Kind::perimeter) return fabric.on_perimeter(node);
  if (fabric.spec().shape != FabricSpec::Shape::rectangle) return false;
  const int i = fabric.i_of(node), j = fabric.j_of(node);
  const int last_i = fabric.nodes_warp() - 1, last_j = fabric.nodes_weft() - 1;
  switch (kind) {
    case Kind::edge_left: return i == 0;
    case Kind::edge_right: return i == last_i;
    case Kind::edge_bottom: return j == 0;
    case Kind::edge_top: return j == last_j;
    case Kind::corners: return (i == 0 || i == last_i) && (j == 0 || j == last_j);
    default: return false;
  }
}

int nearest_node(const Fabric& fabric, const Eigen::Vector2d& point) {
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < fabric.node_count(); ++k) {
    const double distance = (fabric.rest_position(k).head<2>() - point).squaredNorm();
    if (distance < best_distance) best = k, best_distance = distance;
  }
  return best;
}

bool in_box(const Eigen::Vector2d& p, const NodeSetSpec& spec) {
  return (p.array() >= spec.box_min.array()).all() && (p.array() <= spec.box_max.array()).all();
}

// How far a node of the flat fabric lies inside its edge: to the nearest side of a rectangle,
// to the rim of a circle.
double depth_inside(const Fabric& fabric, int node) {
  const Eigen::Vector2d p = fabric.rest_position(node).head<2>();
  const FabricSpec& spec = fabric.spec();
  if (spec.shape == FabricSpec::Shape::circle)
    return spec.radius_m() - (p - Eigen::Vector2d(spec.radius_m(), spec.radius_m())).norm();
  return std::min({p.x(), spec.width_m - p.x(), p.y(), spec.height_m - p.y()});
}

bool selected(const Fabric& fabric, const NodeSetSpec& spec, int node) {
  using Kind = NodeSetSpec::Kind;
  if (spec.kind == Kind::box) return in_box(fabric.rest_position(node).head<2>(), spec);
  // A node on the frame's inner line belongs to it, whatever the rounding of its position.
  if (spec.kind == Kind::frame) return depth_inside(fabric, node) <= spec.width_m * (1.0 + 1e-9);
  if (spec.kind == Kind::disc)
    return (fabric.rest_position(node).head<2>() - spec.point).norm() <= spec.width_m * (1.0 + 1e-9);
  return in_named_set(fabric, spec.kind, node);
}

}  // namespace

std::vector<int> select_nodes(const Fabric& fabric, const NodeSetSpec& spec) {
  using Kind = NodeSetSpec::Kind;
  std::vector<int> nodes;
  if (spec.kind == Kind::index) {
    if (const int k = fabric.node(spec.i, spec.j); k >= 0) nodes.push_back(k);
    return nodes;
  }
  if (spec.kind == Kind::nearest) return {nearest_node(fabric, spec.point)};
  for (int k = 0; k < fabric.node_count(); ++k)
    if (selected(fabric, spec, k)) nodes.push_back(k);
  return nodes;
}

bool parse_axes(const std::string& text, AxisMask* mask) {
  AxisMask result = 0;
  for (const char c : text) {
    const AxisMask bit = c == 'x' ? kLockX : c == 'y' ? kLockY : c == 'z' ? kLockZ : 0;
    if (bit == 0 || (result & bit)) return false;
    result = static_cast<AxisMask>(result | bit);
  }
  if (result == 0) return false;
  *mask = result;
  return true;
}

std::string axes_to_string(AxisMask mask) {
  std::string text;
  if (mask & kLockX) text += 'x';
  if (mask & kLockY) text += 'y';
  if (mask & kLockZ) text += 'z';
  return text;
}

Eigen::Vector3d remove_locked(const Eigen::Vector3d& v, AxisMask mask) {
  Eigen::Vector3d free = v;
  for (int axis = 0; axis < 3; ++axis)
    if (mask & (1 << axis)) free[axis] = 0.0;
  return free;
}

}  // namespace fabform
