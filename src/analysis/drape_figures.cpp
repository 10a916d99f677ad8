#include "fabform/analysis/drape_figures.hpp"

#include <algorithm>
#include <cmath>

#include "fabform/angles.hpp"
#include "fabform/analysis/drape_coefficient.hpp"

namespace fabform {
namespace {

// The outline resampled at even steps along it and averaged over a window: a lattice circle's
// outline is a staircase of cell-sized steps, which a window of three cells flattens; folds span
// many cells and keep their depth.
std::vector<Eigen::Vector2d> smoothed(const std::vector<Eigen::Vector2d>& outline, double window_m) {
  const std::size_t n = outline.size();
  if (window_m <= 0.0 || n < 3) return outline;
  std::vector<double> along(n + 1, 0.0);  // arc length to each corner, and round to the start again
  for (std::size_t k = 0; k < n; ++k) along[k + 1] = along[k] + (outline[(k + 1) % n] - outline[k]).norm();
  const double step = window_m / 12.0;
  const auto samples = static_cast<std::size_t>(std::ceil(along[n] / step));
  std::vector<Eigen::Vector2d> even(samples);
  std::size_t side = 0;
  for (std::size_t k = 0; k < samples; ++k) {
    const double s = along[n] * static_cast<double>(k) / static_cast<double>(samples);
    while (along[side + 1] < s) ++side;
    const double t = along[side + 1] > along[side] ? (s - along[side]) / (along[side + 1] - along[side]) : 0.0;
    even[k] = (1.0 - t) * outline[side] + t * outline[(side + 1) % n];
  }
  const std::size_t half = std::min<std::size_t>(6, (samples - 1) / 2);
  std::vector<Eigen::Vector2d> out(samples, Eigen::Vector2d::Zero());
  for (std::size_t k = 0; k < samples; ++k) {
    for (std::size_t j = samples + k - half; j <= samples + k + half; ++j) out[k] += even[j % samples];
    out[k] /= static_cast<double>(2 * half + 1);
  }
  return out;
}

double enclosed_area(const std::vector<Eigen::Vector2d>& ring) {
  double twice = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Eigen::Vector2d& a = ring[k];
    const Eigen::Vector2d& b = ring[(k + 1) % ring.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

const std::vector<Eigen::Vector2d>* largest_outline(const Shadow& shadow) {
  const auto largest = std::max_element(
      shadow.outlines.begin(), shadow.outlines.end(),
      [](const auto& p, const auto& q) { return enclosed_area(p) < enclosed_area(q); });
  return largest == shadow.outlines.end() ? nullptr : &*largest;
}

// The flat specimen's outline, smoothed alike, as (angle, distance) about its centre sorted by
// angle: a lattice circle is not round (its cells cut it most near the diagonals), and that
// shape is no fold.
std::vector<std::pair<double, double>> flat_outline(const Fabric& fabric, double window_m) {
  std::vector<Eigen::Vector3d> rest;
  for (int k = 0; k < fabric.node_count(); ++k) rest.push_back(fabric.rest_position(k));
  const Shadow flat = fabric_shadow(rest, face_triangles(fabric.faces()));
  const double r = fabric.spec().radius_m();
  std::vector<std::pair<double, double>> polar;
  for (const Eigen::Vector2d& p : smoothed(*largest_outline(flat), window_m)) {
    const Eigen::Vector2d d = p - Eigen::Vector2d(r, r);
    polar.emplace_back(std::atan2(d.y(), d.x()), d.norm());
  }
  std::sort(polar.begin(), polar.end());
  return polar;
}

// The flat outline's distance at an angle, linear between its neighbours (round the circle).
double distance_at(const std::vector<std::pair<double, double>>& polar, double angle) {
  const auto next = std::lower_bound(polar.begin(), polar.end(), std::pair<double, double>{angle, -1.0});
  const auto& after = next == polar.end() ? polar.front() : *next;
  const auto& before = next == polar.begin() ? polar.back() : *(next - 1);
  double span = after.first - before.first, into = angle - before.first;
  if (span <= 0.0) span += 2.0 * kPi;
  if (into < 0.0) into += 2.0 * kPi;
  return before.second + (after.second - before.second) * std::min(into / span, 1.0);
}

// The draped outline with each point's distance from the centre scaled by R over the flat
// outline's at its angle: a fabric left flat becomes the round circle exactly.
std::vector<Eigen::Vector2d> as_if_round(std::vector<Eigen::Vector2d> outline,
                                         const std::vector<std::pair<double, double>>& flat,
                                         const Eigen::Vector2d& centre_m, const Fabric& fabric) {
  for (Eigen::Vector2d& p : outline) {
    const Eigen::Vector2d d = p - centre_m;
    const double reach = distance_at(flat, std::atan2(d.y(), d.x()));
    if (reach > 0.0) p = centre_m + d * (fabric.spec().radius_m() / reach);
  }
  return outline;
}
}  // namespace

double support_area(const TriangleMesh& mesh) {
  return fabric_shadow(mesh.vertices, mesh.triangles).area_m2;
}

DrapeFigures drape_figures(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x,
                           const Eigen::Vector2d& centre_m, double support_area_m2) {
  const Shadow shadow = fabric_shadow(x, face_triangles(fabric.faces()));
  DrapeFigures f;
  f.shadow_area_m2 = shadow.area_m2;
  f.specimen_area_m2 = fabric.flat_area();
  f.support_area_m2 = support_area_m2;
  f.coefficient = drape_coefficient(shadow.area_m2, f.specimen_area_m2, support_area_m2);
  f.shadow_pieces = shadow.components;
  if (const std::vector<Eigen::Vector2d>* outline = largest_outline(shadow)) {
    const double window = fabric.spec().mesh == FabricSpec::Mesh::arc
                              ? 0.0
                              : 3.0 * std::max(fabric.spacing_warp(), fabric.spacing_weft());
    f.folds = count_folds(as_if_round(smoothed(*outline, window), flat_outline(fabric, window), centre_m, fabric),
                          centre_m, 0.02 * fabric.spec().radius_m());
  }
  return f;
}

}  // namespace fabform
