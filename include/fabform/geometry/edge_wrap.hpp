#pragma once
// A spring over a body's sharp convex edge. Contact is the nodes' (seed 003): a straight spring
// between two nodes outside a body may still pass through it under an edge. Where a spring's
// segment passes under an edge (through the wedge the edge's two faces enclose), it wraps the
// edge as a string wraps a sharp corner: it runs from a to the point p of the edge that makes
// |a − p| + |p − b| least, and on to b. That point is found by unfolding: turned about the edge
// line into one plane with a, b lies straight across from it, so p divides the edge line in the
// ratio of a's and b's distances from it (the geodesic over a dihedral, in closed form).
#include <optional>

#include <Eigen/Core>

namespace fabform {

/// A convex edge of a body: its ends, and its two faces' outward normals.
struct SharpEdge {
  Eigen::Vector3d from = Eigen::Vector3d::Zero();
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal_a = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d normal_b = Eigen::Vector3d::UnitX();
};

/// How a spring between a and b runs over an edge it wraps.
struct EdgeWrap {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // p, on the edge
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();   // the edge's unit direction
  double length = 0.0;                               // |a − p| + |p − b|
  bool at_end = false;  // p is held at an end of the edge rather than free to slide along it
};

/// The wrap of the segment a–b over `edge`, when the segment passes under it: its closest approach
/// to the edge line lies strictly inside the wedge, strictly between a and b, within the edge's
/// length and no farther from it than the segment is long (beyond that the edge's faces no longer
/// bound the body). As the segment rises to touch the edge, the wrap's length falls to |a − b|.
/// A closest approach within `end_margin_m` of the edge's ends does not count: a segment lying on
/// a face that an edge ends at (a spring on a box's top, by its vertical edge) meets the edge line
/// there, and only rounding would say whether it passes under it.
std::optional<EdgeWrap> wrap_over(const SharpEdge& edge, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  double end_margin_m);

}  // namespace fabform
