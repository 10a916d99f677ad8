#pragma once
// Triangles of one polygonal face as CAD files list it (OBJ n-gons): concave and slightly
// non-planar faces included, by ear clipping in the face's best-fit plane (Newell's normal).
#include <array>
#include <vector>

#include <Eigen/Core>

namespace fabform {

/// Newell's normal of a closed polygon: twice its vector area, pointing the way its corners
/// turn counter-clockwise. Exact for a planar polygon, the best-fit plane's normal otherwise.
Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d>& corners);

/// The n - 2 triangles (indices into `corners`, wound as the polygon is) that cover a simple
/// polygon of n >= 3 corners and nothing outside it. Repeated and collinear corners give
/// zero-area triangles (mesh repair drops them); a polygon of no area (all corners on a line)
/// is fanned. A polygon that crosses itself has no inside: it is still cut into n - 2
/// triangles, the ears found first.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector3d>& corners);

}  // namespace fabform
