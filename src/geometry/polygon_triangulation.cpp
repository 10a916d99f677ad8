#include "fabform/geometry/polygon_triangulation.hpp"

#include <Eigen/Geometry>
#include <cstddef>

namespace fabform {
namespace {

using Point2 = Eigen::Vector2d;

double cross(const Point2& a, const Point2& b, const Point2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// Corners in the plane through the centroid normal to n, axes chosen so that the polygon turns
// counter-clockwise there (positive area).
std::vector<Point2> projected(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& n) {
  const Eigen::Vector3d w = n.normalized();
  const Eigen::Vector3d u = w.unitOrthogonal();
  const Eigen::Vector3d v = w.cross(u);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : corners) centre += p;
  centre /= static_cast<double>(corners.size());
  std::vector<Point2> out;
  for (const auto& p : corners) out.emplace_back((p - centre).dot(u), (p - centre).dot(v));
  return out;
}

// Whether p lies in triangle abc (counter-clockwise) or on its boundary: a corner on the
// boundary of an ear would be cut off by it.
bool inside_or_on(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  return cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0;
}

// Ear clipping over a ring of corners linked both ways. Only reflex corners can lie inside an
// ear, so only they are tested: a convex polygon is cut in linear time.
class EarClipper {
 public:
  explicit EarClipper(std::vector<Point2> points)
      : points_(std::move(points)), prev_(points_.size()), next_(points_.size()), reflex_(points_.size()) {
    const std::size_t n = points_.size();
    for (std::size_t i = 0; i < n; ++i) prev_[i] = (i + n - 1) % n, next_[i] = (i + 1) % n;
    for (std::size_t i = 0; i < n; ++i) mark_if_reflex(i);
  }

  std::vector<std::array<int, 3>> run() {
    std::vector<std::array<int, 3>> triangles;
    std::size_t i = 0, remaining = points_.size(), tried = 0;
    while (remaining > 3) {
      if (is_ear(i) || tried == remaining) {  // after a lap without an ear, the least bad corner
        if (tried == remaining) i = leftmost_turn(i);
        triangles.push_back(triangle(i));
        i = clip(i);
        --remaining, tried = 0;
      } else {
        i = next_[i], ++tried;
      }
    }
    triangles.push_back(triangle(i));
    return triangles;
  }

 private:
  double turn(std::size_t i) const { return cross(points_[prev_[i]], points_[i], points_[next_[i]]); }
  std::array<int, 3> triangle(std::size_t i) const {
    return {static_cast<int>(prev_[i]), static_cast<int>(i), static_cast<int>(next_[i])};
  }

  void mark_if_reflex(std::size_t i) {
    reflex_[i] = !(turn(i) > 0.0);
    if (reflex_[i]) reflex_list_.push_back(i);  // may repeat; stale entries are skipped
  }

  // An ear: a convex corner whose triangle holds no reflex corner of the ring (corners at the
  // same place as one of its own do not block it: a repeated point is no obstacle).
  bool is_ear(std::size_t i) const {
    if (reflex_[i]) return false;
    const Point2 &a = points_[prev_[i]], &b = points_[i], &c = points_[next_[i]];
    for (const std::size_t k : reflex_list_) {
      if (!reflex_[k] || clipped(k)) continue;
      const Point2& p = points_[k];
      if (p == a || p == b || p == c) continue;
      if (inside_or_on(p, a, b, c)) return false;
    }
    return true;
  }

  bool clipped(std::size_t k) const { return next_[prev_[k]] != k; }

  // Unlinks corner i; its neighbours turn anew. Returns the next corner.
  std::size_t clip(std::size_t i) {
    const std::size_t a = prev_[i], c = next_[i];
    next_[a] = c, prev_[c] = a;
    for (const std::size_t k : {a, c}) {
      const bool was = reflex_[k];
      reflex_[k] = !(turn(k) > 0.0);
      if (reflex_[k] && !was) reflex_list_.push_back(k);
    }
    return c;
  }

  // The corner of the ring that turns most to the left, starting from i.
  std::size_t leftmost_turn(std::size_t i) const {
    std::size_t best = i;
    for (std::size_t k = next_[i]; k != i; k = next_[k])
      if (turn(k) > turn(best)) best = k;
    return best;
  }

  std::vector<Point2> points_;
  std::vector<std::size_t> prev_, next_;
  std::vector<char> reflex_;
  std::vector<std::size_t> reflex_list_;
};

}  // namespace

Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d>& corners) {
  // Summed about the first corner, not the origin: far from the origin the terms would be
  // large and cancel, losing the digits that the area is made of.
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) n += (corners[i] - corners[0]).cross(corners[i + 1] - corners[0]);
  return n;
}

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector3d>& corners) {
  const Eigen::Vector3d n = newell_normal(corners);
  if (corners.size() == 3 || n.squaredNorm() == 0.0) {
    std::vector<std::array<int, 3>> fan;
    for (int i = 1; i + 1 < static_cast<int>(corners.size()); ++i) fan.push_back({0, i, i + 1});
    return fan;
  }
  return EarClipper(projected(corners, n)).run();
}

}  // namespace fabform
