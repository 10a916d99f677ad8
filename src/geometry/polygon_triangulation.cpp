#include "fabform/geometry/polygon_triangulation.hpp"

#include <Eigen/Geometry>
#include <cstddef>
#include <numeric>

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

class EarClipper {
 public:
  explicit EarClipper(std::vector<Point2> points) : points_(std::move(points)), ring_(points_.size()) {
    std::iota(ring_.begin(), ring_.end(), 0);
  }

  std::vector<std::array<int, 3>> run() {
    std::vector<std::array<int, 3>> triangles;
    while (ring_.size() > 3) {
      const std::size_t i = next_ear();
      triangles.push_back({corner(i + ring_.size() - 1), corner(i), corner(i + 1)});
      ring_.erase(ring_.begin() + static_cast<std::ptrdiff_t>(i));
    }
    triangles.push_back({corner(0), corner(1), corner(2)});
    return triangles;
  }

 private:
  int corner(std::size_t i) const { return ring_[i % ring_.size()]; }
  const Point2& at(std::size_t i) const { return points_[static_cast<std::size_t>(corner(i))]; }
  double turn(std::size_t i) const { return cross(at(i + ring_.size() - 1), at(i), at(i + 1)); }

  // An ear: a convex corner whose triangle holds no other corner of the ring (corners at the
  // same place as one of its own do not block it: a repeated point is no obstacle).
  bool is_ear(std::size_t i) const {
    if (!(turn(i) > 0.0)) return false;
    const Point2 &a = at(i + ring_.size() - 1), &b = at(i), &c = at(i + 1);
    for (std::size_t k = 0; k < ring_.size(); ++k) {
      const Point2& p = at(k);
      if (p == a || p == b || p == c) continue;
      if (turn(k) <= 0.0 && inside_or_on(p, a, b, c)) return false;  // only reflex corners can be inside
    }
    return true;
  }

  // The first ear; when there is none (what is left has no area, or crosses itself), the corner
  // that turns most to the left, so that clipping always ends.
  std::size_t next_ear() const {
    std::size_t best = 0;
    for (std::size_t i = 0; i < ring_.size(); ++i) {
      if (is_ear(i)) return i;
      if (turn(i) > turn(best)) best = i;
    }
    return best;
  }

  std::vector<Point2> points_;
  std::vector<int> ring_;
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
