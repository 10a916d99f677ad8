#include "fabform/analysis/drape_figures.hpp"

#include <algorithm>

#include "fabform/analysis/drape_coefficient.hpp"

namespace fabform {
namespace {
// How far the flat specimen's own outline rises and falls about its centre: a lattice circle's
// staircase, which no fold count should see as folds.
double flat_outline_wiggle(const Fabric& fabric) {
  const Eigen::Vector3d centre(fabric.spec().radius_m(), fabric.spec().radius_m(), 0.0);
  double nearest = fabric.spec().radius_m(), farthest = 0.0;
  for (int k = 0; k < fabric.node_count(); ++k) {
    if (!fabric.on_perimeter(k)) continue;
    const double r = (fabric.rest_position(k) - centre).head<2>().norm();
    nearest = std::min(nearest, r), farthest = std::max(farthest, r);
  }
  return farthest - nearest;
}
}  // namespace

std::vector<std::array<int, 3>> fabric_triangles(const Fabric& fabric) {
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(2 * fabric.faces().size());
  for (const Face& f : fabric.faces()) {
    triangles.push_back({f.corner[0], f.corner[1], f.corner[2]});
    if (f.corners == 4) triangles.push_back({f.corner[0], f.corner[2], f.corner[3]});
  }
  return triangles;
}

double support_area(const TriangleMesh& mesh) {
  return fabric_shadow(mesh.vertices, mesh.triangles).area_m2;
}

DrapeFigures drape_figures(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x,
                           const Eigen::Vector2d& centre_m, double support_area_m2) {
  const Shadow shadow = fabric_shadow(x, fabric_triangles(fabric));
  DrapeFigures f;
  f.shadow_area_m2 = shadow.area_m2;
  f.specimen_area_m2 = fabric.flat_area();
  f.support_area_m2 = support_area_m2;
  f.coefficient = drape_coefficient(shadow.area_m2, f.specimen_area_m2, support_area_m2);
  f.shadow_pieces = shadow.components;
  const auto largest = std::max_element(
      shadow.outlines.begin(), shadow.outlines.end(),
      [](const auto& p, const auto& q) { return p.size() < q.size(); });
  if (largest != shadow.outlines.end())
    f.folds = count_folds(*largest, centre_m, std::max(0.02 * fabric.spec().radius_m(), flat_outline_wiggle(fabric)));
  return f;
}

}  // namespace fabform
