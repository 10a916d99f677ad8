#pragma once
// A sewing pattern's panel outline: a closed loop of edges in the panel's own plane, each a
// straight line, a quadratic or cubic Bézier curve or a circular arc, as pattern software
// draws them (GarmentCode, CLO's and Marvelous Designer's pattern windows). Edge k runs from
// vertex k to vertex k + 1 (the last back to vertex 0). The outline is traced as a fine
// polyline that remembers, for every point, its edge and its arc length along it, so that a
// lattice's boundary nodes can be put on the outline and seams matched by arc length.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace fabform {

struct OutlineEdge {
  enum class Kind { straight, quadratic, cubic, arc };
  Kind kind = Kind::straight;
  std::vector<Eigen::Vector2d> controls;  // quadratic: 1, cubic: 2 (absolute, m)
  // arc: a circle of this radius through both ends, turning counter-clockwise (seen from +z)
  // or clockwise from start to end, the shorter or the longer way round.
  double radius_m = 0.0;
  bool counter_clockwise = true;
  bool large_arc = false;
};

struct PanelOutline {
  std::vector<Eigen::Vector2d> vertices;  // m
  std::vector<OutlineEdge> edges;         // one per vertex: edge k leaves vertex k

  /// Why the outline is no closed, simple loop (fewer than 3 vertices, an edge of no length,
  /// a control count that does not fit the curve, an arc's radius shorter than half its chord,
  /// the loop crossing itself), or "".
  std::string invalid_reason() const;
  /// A bound on the outline's length: arcs' own, Bézier curves' control polygons.
  double length_bound() const;
  /// The point at parameter t ∈ [0, 1] of edge k (t is the curve's own parameter, not arc length).
  Eigen::Vector2d point(int edge, double t) const;
};

/// The outline as a closed polyline: point k lies on edge[k] at curve parameter t[k] and arc
/// length s[k] from its start; each edge's points run from its start vertex (s = 0) up to, not
/// including, its end vertex.
struct TracedOutline {
  PanelOutline outline;
  std::vector<Eigen::Vector2d> points;
  std::vector<int> edge;
  std::vector<double> t;
  std::vector<double> s;
  std::vector<double> edge_length;  // per edge, m
  std::vector<int> edge_first;      // per edge, its first point

  /// The area the outline encloses, positive when it runs counter-clockwise (m²).
  double signed_area() const;
  /// Whether p lies inside the outline (even–odd rule).
  bool contains(const Eigen::Vector2d& p) const;
  /// The point of edge k at arc length s from its start (clamped to the edge), on the curve
  /// itself: its parameter interpolated between the traced points around it.
  Eigen::Vector2d at(int edge, double s) const;
  /// The arc length along edge k of the point of that edge nearest to p.
  double nearest_s(int edge, const Eigen::Vector2d& p) const;
  /// The range [first, end) of edge k's traced points.
  std::pair<std::size_t, std::size_t> edge_points(int edge) const;
};

/// The outline traced with segments no longer than max_segment_m, at least 8 an edge (straight
/// ones too), arc lengths accurate to the polyline at that resolution. The outline must be valid.
TracedOutline trace_outline(const PanelOutline& outline, double max_segment_m);

}  // namespace fabform
