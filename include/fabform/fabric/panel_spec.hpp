#pragma once
// A garment's panel: an outline cut from the cloth, its grain (the warp's direction in it), and
// where the pattern places it round the body. fabform meshes it as the fabric's lattice, laid
// along the grain, clipped to the outline, with the lattice's boundary nodes moved onto the
// outline (fabric_layout.hpp, panel_layout), so warp and weft springs keep their own tables and
// every edge of the outline is a chain of nodes a seam can sew.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/geometry/panel_outline.hpp"

namespace fabform {

struct PanelSpec {
  std::string name;
  PanelOutline outline;     // m, in the panel's own plane
  double grain_deg = 0.0;   // the warp's direction in that plane, from its first axis
  // The pattern's placement of the panel's plane (initial shape "pattern"): a point (u, v) of it
  // starts at rotation · (u, v, 0) + translation_m.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
};

/// A panel as meshed: its nodes (contiguous), and for every edge of its outline the nodes on it
/// from its start vertex to its end vertex, both corners included.
struct PanelMesh {
  std::string name;
  int first_node = 0;
  int node_count = 0;
  std::vector<std::vector<int>> edge_nodes;
  // A flat position f of the panel's nodes is the point R(grain) · (f + flat_to_plane) of the
  // panel's plane.
  Eigen::Vector2d flat_to_plane = Eigen::Vector2d::Zero();
  double grain_rad = 0.0;

  Eigen::Vector2d plane_point(const Eigen::Vector3d& flat) const;
};

/// The panel's placement in space: the point of its plane at (u, v) placed as PanelSpec says.
Eigen::Vector3d placed_point(const PanelSpec& panel, const Eigen::Vector2d& plane_point);

}  // namespace fabform
