#pragma once
// What a run with fabric–fabric contact reports of it: how many node–triangle pairs lie closer
// than the thickness (the penalty holding plies apart), the smallest such distance, and CGAL's
// count of intersecting triangle pairs (self_intersections.hpp), the independent check that no
// ply went through another.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

struct PlyFigures {
  double thickness_m = 0.0;
  int contact_pairs = 0;                 // node–triangle pairs closer than the thickness
  std::optional<double> smallest_gap_m;  // the least distance among them; none without a pair
  int intersecting_triangle_pairs = 0;
};

/// The figures at x; none for a model without self-contact.
std::optional<PlyFigures> ply_figures(const Model& model, const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
