#include "fabform/geometry/edge_wrap.hpp"

#include <algorithm>
#include <cmath>

namespace fabform {
namespace {

// A segment closer than this to parallel with the edge (sin² of the angle between them) cannot
// wrap it: it would lie along it.
constexpr double kParallel = 1e-12;

// Parameters (t on a–b, s on the edge line from its start, in the edge's own units) of the two
// lines' closest approach; none when they are parallel.
std::optional<Eigen::Vector2d> closest_approach(const Eigen::Vector3d& a, const Eigen::Vector3d& u,
                                                const Eigen::Vector3d& q, const Eigen::Vector3d& v) {
  const Eigen::Vector3d w = a - q;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), uw = u.dot(w), vw = v.dot(w);
  const double denominator = uu * vv - uv * uv;
  if (!(denominator > kParallel * uu * vv)) return std::nullopt;
  return Eigen::Vector2d((uv * vw - vv * uw) / denominator, (uu * vw - uv * uw) / denominator);
}

}  // namespace

std::optional<EdgeWrap> wrap_over(const SharpEdge& edge, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  double end_margin_m) {
  const Eigen::Vector3d u = b - a, v = edge.to - edge.from;
  const double edge_length = v.norm();
  if (edge_length == 0.0) return std::nullopt;
  const auto ts = closest_approach(a, u, edge.from, v);
  if (!ts) return std::nullopt;
  const double t = (*ts)[0], s = (*ts)[1];
  const double margin = end_margin_m / edge_length;
  if (!(t > 0.0 && t < 1.0 && s >= margin && s <= 1.0 - margin)) return std::nullopt;
  const Eigen::Vector3d below = (a + t * u) - (edge.from + s * v);  // from the edge to the segment
  if (!(below.dot(edge.normal_a) < 0.0 && below.dot(edge.normal_b) < 0.0)) return std::nullopt;
  if (below.norm() > u.norm()) return std::nullopt;

  // Unfolded: a and b at their distances ρ from the edge line on either side of it, at their
  // positions σ along it; the straight line between them crosses the line at σ_a + (σ_b − σ_a)·ρ_a/(ρ_a + ρ_b).
  EdgeWrap wrap;
  wrap.axis = v / edge_length;
  const double sigma_a = (a - edge.from).dot(wrap.axis), sigma_b = (b - edge.from).dot(wrap.axis);
  const double rho_a = (a - edge.from - sigma_a * wrap.axis).norm();
  const double rho_b = (b - edge.from - sigma_b * wrap.axis).norm();
  if (!(rho_a > 0.0 && rho_b > 0.0)) return std::nullopt;
  const double crossing = sigma_a + (sigma_b - sigma_a) * rho_a / (rho_a + rho_b);
  const double along = std::clamp(crossing, 0.0, edge_length);
  wrap.at_end = along != crossing;
  wrap.point = edge.from + along * wrap.axis;
  wrap.length = (a - wrap.point).norm() + (b - wrap.point).norm();
  return wrap;
}

}  // namespace fabform
