// triangulate_polygon against oracles of its own: on concave faces (L, U, comb, star, spiral),
// in both windings, from every starting corner, in tilted planes far from the origin, the
// triangles' areas sum to the polygon's (shoelace) area, every triangle turns the polygon's way,
// and points inside every triangle lie inside the polygon (crossing number): so they cover it
// exactly, and nothing outside. Degenerate faces swept: repeated and collinear corners, a face
// of no area, non-planar faces. Tolerances are relative to the polygon's size squared.
#include "fabform/geometry/polygon_triangulation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace fabform::polygon_triangulation_test {
namespace {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;
using Polygon2 = std::vector<V2>;

double shoelace(const Polygon2& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) twice += p[i].x() * p[(i + 1) % p.size()].y() - p[(i + 1) % p.size()].x() * p[i].y();
  return 0.5 * twice;
}

// Crossing number: whether q lies inside the polygon (q must not be on its boundary).
bool inside(const Polygon2& p, const V2& q) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    if ((p[i].y() > q.y()) != (p[j].y() > q.y()) &&
        q.x() < (p[j].x() - p[i].x()) * (q.y() - p[i].y()) / (p[j].y() - p[i].y()) + p[i].x())
      in = !in;
  return in;
}

double signed_area(const V2& a, const V2& b, const V2& c) {
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

// A plane tilted about no axis in particular, far from the origin: the polygon's 2D points
// become 3D corners, and its 2D coordinates are what the oracle measures.
struct Plane {
  V3 origin{1.0e3, -2.5e2, 7.0e2};
  Eigen::Matrix3d axes = Eigen::AngleAxisd(0.7, V3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  V3 to_3d(const V2& p) const { return origin + axes.col(0) * p.x() + axes.col(1) * p.y(); }
  std::vector<V3> to_3d(const Polygon2& p) const {
    std::vector<V3> out;
    for (const V2& q : p) out.push_back(to_3d(q));
    return out;
  }
};

Polygon2 rotated(Polygon2 p, std::size_t start) {
  std::rotate(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(start), p.end());
  return p;
}

Polygon2 reversed(Polygon2 p) {
  std::reverse(p.begin(), p.end());
  return p;
}

double size_squared(const Polygon2& p) {
  Eigen::AlignedBox2d box;
  for (const V2& q : p) box.extend(q);
  return box.sizes().squaredNorm();
}

// The polygon's 2D points are triangulated through 3D; checks coverage exactly as the header says.
void expect_exact_cover(const Polygon2& p, const std::string& name) {
  const Plane plane;
  const auto triangles = triangulate_polygon(plane.to_3d(p));
  ASSERT_EQ(triangles.size(), p.size() - 2) << name;
  const double orientation = shoelace(p) > 0 ? 1.0 : -1.0;
  const double tolerance = 1e-12 * size_squared(p);
  double sum = 0.0;
  for (const auto& t : triangles) {
    for (const int i : t) ASSERT_TRUE(i >= 0 && i < static_cast<int>(p.size())) << name;
    const V2 &a = p[static_cast<std::size_t>(t[0])], &b = p[static_cast<std::size_t>(t[1])], &c = p[static_cast<std::size_t>(t[2])];
    const double area = orientation * signed_area(a, b, c);
    EXPECT_GE(area, -tolerance) << name << ": a triangle turns the other way";
    sum += area;
    if (area <= tolerance) continue;  // no inside to sample
    for (const V3& w : {V3(1 / 3.0, 1 / 3.0, 1 / 3.0), V3(0.8, 0.1, 0.1), V3(0.1, 0.8, 0.1), V3(0.1, 0.1, 0.8)})
      EXPECT_TRUE(inside(p, w[0] * a + w[1] * b + w[2] * c)) << name << ": a triangle reaches outside the polygon";
  }
  EXPECT_NEAR(sum, std::abs(shoelace(p)), tolerance) << name;
}

// Concave faces, counter-clockwise as listed.
std::vector<std::pair<std::string, Polygon2>> concave_faces() {
  Polygon2 star, spiral, comb;
  for (int i = 0; i < 10; ++i) {
    const double r = i % 2 ? 0.4 : 1.0, a = 2.0 * M_PI * i / 10;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  // A thick spiral: out along one arm, back along a wider one.
  Polygon2 back;
  for (int i = 0; i <= 30; ++i) {
    const double a = 0.25 * i, r = 1.0 + 0.3 * a;
    spiral.emplace_back(r * std::cos(a), r * std::sin(a));
    back.emplace_back((r + 0.25) * std::cos(a), (r + 0.25) * std::sin(a));
  }
  spiral.insert(spiral.end(), back.rbegin(), back.rend());
  if (shoelace(spiral) < 0) spiral = reversed(spiral);
  comb = {{0, 0}, {7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  return {{"L", {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}},
          {"U", {{0, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1}, {1, 1}, {1, 3}, {0, 3}}},
          {"arrow", {{0, 0}, {2, 1}, {4, 0}, {2, 3}}},
          {"star", star},
          {"comb", comb},
          {"spiral", spiral}};
}

TEST(PolygonTriangulation, ConcaveFacesAreCoveredExactlyInBothWindingsFromEveryCorner) {
  for (const auto& [name, polygon] : concave_faces())
    for (const Polygon2& p : {polygon, reversed(polygon)})
      for (std::size_t start = 0; start < p.size(); ++start)
        expect_exact_cover(rotated(p, start), name + " from corner " + std::to_string(start));
}

TEST(PolygonTriangulation, TrianglesKeepTheFacesWinding) {
  const Plane plane;
  for (const auto& [name, polygon] : concave_faces())
    for (const Polygon2& p : {polygon, reversed(polygon)}) {
      const std::vector<V3> corners = plane.to_3d(p);
      const V3 n = newell_normal(corners);
      EXPECT_NEAR(n.norm(), 2.0 * std::abs(shoelace(p)), 1e-9 * size_squared(p)) << name;
      for (const auto& t : triangulate_polygon(corners)) {
        const V3& a = corners[static_cast<std::size_t>(t[0])];
        EXPECT_GT((corners[static_cast<std::size_t>(t[1])] - a).cross(corners[static_cast<std::size_t>(t[2])] - a).dot(n), 0.0) << name;
      }
    }
}

TEST(PolygonTriangulation, RepeatedAndCollinearCornersAreSwept) {
  const Polygon2 l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  // Every corner repeated in turn, then a midpoint put on every edge in turn (a straight corner).
  for (std::size_t i = 0; i < l.size(); ++i) {
    Polygon2 repeated = l;
    repeated.insert(repeated.begin() + static_cast<std::ptrdiff_t>(i), l[i]);
    Polygon2 straight = l;
    straight.insert(straight.begin() + static_cast<std::ptrdiff_t>(i + 1), 0.5 * (l[i] + l[(i + 1) % l.size()]));
    for (const Polygon2& p : {repeated, straight, reversed(repeated), reversed(straight)})
      for (std::size_t start = 0; start < p.size(); ++start) expect_exact_cover(rotated(p, start), "swept L " + std::to_string(i));
  }
}

TEST(PolygonTriangulation, AFaceOfNoAreaGivesTrianglesOfNoArea) {
  const Plane plane;
  for (const Polygon2& p : {Polygon2{{0, 0}, {1, 0}, {2, 0}, {3, 0}}, Polygon2{{0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}}}) {
    const auto triangles = triangulate_polygon(plane.to_3d(p));
    ASSERT_EQ(triangles.size(), p.size() - 2);
    for (const auto& t : triangles)
      EXPECT_NEAR(signed_area(p[static_cast<std::size_t>(t[0])], p[static_cast<std::size_t>(t[1])], p[static_cast<std::size_t>(t[2])]), 0.0, 1e-15);
  }
}

// A concave face whose corners leave its plane by up to 2 % of its size (a warped CAD n-gon):
// seen along Newell's normal it is covered exactly, and every triangle faces the same way.
TEST(PolygonTriangulation, NonPlanarFacesAreCutInTheirBestFitPlane) {
  for (const auto& [name, polygon] : concave_faces())
    for (const Polygon2& p : {polygon, reversed(polygon)}) {
      std::vector<V3> corners;
      for (std::size_t i = 0; i < p.size(); ++i) corners.emplace_back(p[i].x(), p[i].y(), 0.02 * std::sqrt(size_squared(p)) * std::sin(3.0 * static_cast<double>(i)));
      const V3 n = newell_normal(corners);
      const auto triangles = triangulate_polygon(corners);
      ASSERT_EQ(triangles.size(), p.size() - 2) << name;
      V3 sum = V3::Zero();
      for (const auto& t : triangles) {
        const V3& a = corners[static_cast<std::size_t>(t[0])];
        const V3 area = (corners[static_cast<std::size_t>(t[1])] - a).cross(corners[static_cast<std::size_t>(t[2])] - a);
        EXPECT_GT(area.dot(n), 0.0) << name << ": a triangle folds back";
        sum += area;
      }
      EXPECT_NEAR((sum - n).norm(), 0.0, 1e-12 * size_squared(p)) << name << ": the vector areas differ";
      EXPECT_NEAR(n.z(), 2.0 * shoelace(p), 1e-12 * size_squared(p)) << name;
    }
}

}  // namespace
}  // namespace fabform::polygon_triangulation_test
