#include "fabform/geometry/closest_point.hpp"

#include <algorithm>

namespace fabform {

double closest_parameter_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) return 0.0;
  return std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
}

namespace {

TriangleClosest closest_on_edges(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d* ends[3][2] = {{&a, &b}, {&b, &c}, {&c, &a}};
  const TriangleFeature edges[3] = {TriangleFeature::edge01, TriangleFeature::edge12,
                                    TriangleFeature::edge20};
  TriangleClosest best{a, TriangleFeature::vertex0};
  double best_distance = (p - a).squaredNorm();
  for (int e = 0; e < 3; ++e) {
    const double t = closest_parameter_on_segment(p, *ends[e][0], *ends[e][1]);
    const Eigen::Vector3d q = *ends[e][0] + t * (*ends[e][1] - *ends[e][0]);
    if ((p - q).squaredNorm() < best_distance) {
      best_distance = (p - q).squaredNorm();
      best = {q, edges[e]};
    }
  }
  return best;
}

}  // namespace

// Ericson, Real-Time Collision Detection, §5.1.5: test the vertex, edge and face regions in
// turn with barycentric sign tests.
TriangleClosest closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  // A triangle flatter than an angle of 1e-12 rad has no usable face: its barycentric
  // denominators below are rounding noise.
  if (ab.cross(ac).squaredNorm() <= 1e-24 * ab.squaredNorm() * ac.squaredNorm())
    return closest_on_edges(p, a, b, c);
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, TriangleFeature::vertex0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, TriangleFeature::vertex1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0)
    return {a + (d1 / (d1 - d3)) * ab, TriangleFeature::edge01};
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, TriangleFeature::vertex2};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0)
    return {a + (d2 / (d2 - d6)) * ac, TriangleFeature::edge20};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0)
    return {b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), TriangleFeature::edge12};
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) return closest_on_edges(p, a, b, c);
  return {a + (vb / denominator) * ab + (vc / denominator) * ac, TriangleFeature::face};
}

std::optional<double> segment_plane_crossing(const Eigen::Vector3d& from,
                                             const Eigen::Vector3d& to, const Eigen::Vector3d& a,
                                             const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  const double along = normal.dot(to - from);
  if (along == 0.0) return std::nullopt;
  const double t = normal.dot(a - from) / along;
  if (!(t >= 0.0 && t <= 1.0)) return std::nullopt;
  return t;
}

}  // namespace fabform
