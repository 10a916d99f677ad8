#pragma once
// The independent check of fabric–fabric contact: CGAL's Polygon_mesh_processing
// self_intersections on the fabric's triangles as formed (face_triangles; nodes sewn node for node
// welded into one vertex, as the garment has one point there), counting the pairs of triangles
// that meet beyond a corner or side they share. Exact predicates (CGAL's Epick kernel), so a
// pair is counted whatever its distance: two plies one thickness apart count none, two plies
// through each other many.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// The number of intersecting triangle pairs of the fabric at x.
int count_self_intersections(const Model& model, const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
