#pragma once
// Named sets of fabric nodes a scene constrains: the perimeter, an edge, the corners, one node
// by index, the node nearest a point, the nodes inside a box, a frame of given width round
// the fabric's edge (what a blank holder grips), or a disc (what a drape tester's clamp holds). Points are in the flat
// fabric's own frame (metres from its lower-left corner, warp along x, weft along y).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"

namespace fabform {

struct NodeSetSpec {
  enum class Kind { perimeter, edge_left, edge_right, edge_bottom, edge_top, corners, index,
                    nearest, box, frame, disc };
  Kind kind = Kind::perimeter;
  int i = 0, j = 0;                                      // Kind::index
  Eigen::Vector2d point = Eigen::Vector2d::Zero();       // Kind::nearest; Kind::disc, its centre
  Eigen::Vector2d box_min = Eigen::Vector2d::Zero();     // Kind::box, inclusive
  Eigen::Vector2d box_max = Eigen::Vector2d::Zero();
  double width_m = 0.0;  // Kind::frame: nodes this close to the flat fabric's edge, or closer; Kind::disc: its radius
};

/// Parses "perimeter", "corners", "edge:left|right|bottom|top"; returns false otherwise.
bool parse_named_node_set(const std::string& name, NodeSetSpec* spec);

/// The nodes a spec selects, in increasing order; possibly empty (the caller reports it).
std::vector<int> select_nodes(const Fabric& grid, const NodeSetSpec& spec);

/// Per-node axis locks: bit 0 x, bit 1 y, bit 2 z (seed 003, §3.2.3).
using AxisMask = unsigned char;
constexpr AxisMask kLockX = 1, kLockY = 2, kLockZ = 4;

/// Parses "x", "xy", "xyz", "z"... (each letter once); returns false otherwise.
bool parse_axes(const std::string& text, AxisMask* mask);
std::string axes_to_string(AxisMask mask);

/// Zeroes the locked components of a vector.
Eigen::Vector3d remove_locked(const Eigen::Vector3d& v, AxisMask mask);

}  // namespace fabform
