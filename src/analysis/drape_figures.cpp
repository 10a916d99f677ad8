#include "fabform/analysis/drape_figures.hpp"

#include <algorithm>
#include <cmath>

#include "fabform/analysis/drape_coefficient.hpp"

namespace fabform {
namespace {
// The outline with each corner replaced by the mean of the corners within half a window either
// side along it. A lattice circle's outline is a staircase of cell-sized steps, which a window
// of two cells flattens; folds span many cells and keep their depth.
std::vector<Eigen::Vector2d> smoothed(const std::vector<Eigen::Vector2d>& outline, double window_m) {
  const std::size_t n = outline.size();
  if (window_m <= 0.0 || n < 3) return outline;
  std::vector<double> along(n + 1, 0.0);  // arc length to each corner, and round to the start again
  for (std::size_t k = 0; k < n; ++k) along[k + 1] = along[k] + (outline[(k + 1) % n] - outline[k]).norm();
  const double perimeter = along[n];
  std::vector<Eigen::Vector2d> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    Eigen::Vector2d sum = outline[k];
    int count = 1;
    for (const int direction : {1, -1})
      for (std::size_t step = 1; step < n; ++step) {
        const std::size_t j = (k + n + static_cast<std::size_t>(direction) * step) % n;
        double gap = std::abs(along[j] - along[k]);
        gap = std::min(gap, perimeter - gap);
        if (gap > 0.5 * window_m) break;
        sum += outline[j], ++count;
      }
    out[k] = sum / count;
  }
  return out;
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
  if (largest != shadow.outlines.end()) {
    const bool lattice = fabric.spec().mesh != FabricSpec::Mesh::arc;
    const double window = lattice ? 2.0 * std::max(fabric.spacing_warp(), fabric.spacing_weft()) : 0.0;
    f.folds = count_folds(smoothed(*largest, window), centre_m, 0.02 * fabric.spec().radius_m());
  }
  return f;
}

}  // namespace fabform
