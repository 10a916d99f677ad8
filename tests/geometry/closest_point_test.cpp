// Point–triangle closest points against brute force, over random and degenerate triangles;
// segment–plane crossings.
#include "fabform/geometry/closest_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace fabform::closest_point_test {
namespace {

using V = Eigen::Vector3d;

V point_on_segment(const V& p, const V& a, const V& b) {
  const V ab = b - a;
  const double l2 = ab.squaredNorm();
  if (l2 == 0.0) return a;
  return a + std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) * ab;
}

// Exact reference: the minimum over the three edges (clamped projections) and, when the
// triangle has a plane and the orthogonal projection of p onto it falls inside (three
// signed-area tests against the normal), that projection. Every candidate is a point of the
// triangle, so the reference is never below the true distance; written independently of the
// Voronoi-region method.
double reference_distance(const V& p, const V& a, const V& b, const V& c) {
  double best = std::min({(p - point_on_segment(p, a, b)).norm(), (p - point_on_segment(p, b, c)).norm(),
                          (p - point_on_segment(p, c, a)).norm()});
  const V n = (b - a).cross(c - a);
  if (n.squaredNorm() > 0.0) {
    const V q = p - (n.dot(p - a) / n.squaredNorm()) * n;
    if ((b - a).cross(q - a).dot(n) >= 0.0 && (c - b).cross(q - b).dot(n) >= 0.0 &&
        (a - c).cross(q - c).dot(n) >= 0.0)
      best = std::min(best, (p - q).norm());
  }
  return best;
}

// A coarse second opinion: dense barycentric sampling (an upper bound on the distance).
double sampled_distance(const V& p, const V& a, const V& b, const V& c, int steps) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; i + j <= steps; ++j) {
      const double u = double(i) / steps, v = double(j) / steps;
      best = std::min(best, (p - ((1 - u - v) * a + u * b + v * c)).norm());
    }
  return best;
}

double size_of(const V& a, const V& b, const V& c) {
  return std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
}

// Relative tolerances, times the problem's scale (triangle size plus distance of p from it).
// Well-shaped triangles: the Voronoi-region tests lose a few digits to cancellation, never
// ten. Slivers and needles: the region tests compare differences of products of size s² whose
// true value is of order (s·h)² for a height h; rounding (ε·s²) can misplace the point by up
// to ~ε·s²/h, but never by more than h (the whole triangle is within h of its long edge), so
// the error is at most max over h of min(h, ε·s²/h) = √ε·s.
constexpr double kWellShapedTol = 1e-10;
const double kSliverTol = 2.0 * std::sqrt(std::numeric_limits<double>::epsilon());

// Checks one query: the distance equals the reference, the point lies on the triangle and on
// the reported feature.
void check_query(const V& p, const V& a, const V& b, const V& c, double relative_tol = kWellShapedTol) {
  const TriangleClosest got = closest_point_on_triangle(p, a, b, c);
  ASSERT_TRUE(got.point.allFinite());
  const double reference = reference_distance(p, a, b, c);
  const double scale = size_of(a, b, c) + (p - a).norm();
  const double tol = relative_tol * scale;
  const double distance = (p - got.point).norm();
  EXPECT_LE(distance, reference + tol) << "p " << p.transpose() << " a " << a.transpose() << " b "
                                       << b.transpose() << " c " << c.transpose();
  // The point is on the triangle: its own distance to the triangle is ~0, and so it cannot
  // be closer to p than the true minimum either.
  EXPECT_LE(reference_distance(got.point, a, b, c), tol);
  EXPECT_GE(distance, reference - tol);

  const auto on = [&](const V& x, const V& y) { return (got.point - point_on_segment(got.point, x, y)).norm() <= tol; };
  switch (got.feature) {
    case TriangleFeature::vertex0: EXPECT_EQ(got.point, a); break;
    case TriangleFeature::vertex1: EXPECT_EQ(got.point, b); break;
    case TriangleFeature::vertex2: EXPECT_EQ(got.point, c); break;
    case TriangleFeature::edge01: EXPECT_TRUE(on(a, b)) << got.point.transpose(); break;
    case TriangleFeature::edge12: EXPECT_TRUE(on(b, c)) << got.point.transpose(); break;
    case TriangleFeature::edge20: EXPECT_TRUE(on(c, a)) << got.point.transpose(); break;
    case TriangleFeature::face: {
      // Interior: p − q is normal to the plane, the barycentrics are in [0, 1].
      const V n = (b - a).cross(c - a);
      ASSERT_GT(n.norm(), 0.0) << "face reported on a triangle without a plane";
      const V d = p - got.point;
      EXPECT_LE(d.cross(n.normalized()).norm(), tol) << "p - q is not along the normal";
      const double area = n.norm();
      const double u = (c - b).cross(got.point - b).dot(n) / (area * area);
      const double v = (a - c).cross(got.point - c).dot(n) / (area * area);
      const double w = (b - a).cross(got.point - a).dot(n) / (area * area);
      const double bary_tol = 1e-9 * scale * size_of(a, b, c) / area;
      EXPECT_GE(u, -bary_tol);
      EXPECT_GE(v, -bary_tol);
      EXPECT_GE(w, -bary_tol);
      break;
    }
  }
}

V random_point(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

class ClosestPointRandom : public ::testing::TestWithParam<double> {};  // coordinate scale

TEST_P(ClosestPointRandom, MatchesBruteForce) {
  const double scale = GetParam();
  std::mt19937 rng(1234u);
  for (int t = 0; t < 400; ++t) {
    const V a = random_point(rng, scale), b = random_point(rng, scale), c = random_point(rng, scale);
    for (int q = 0; q < 10; ++q) {
      // Mostly near the triangle, some far away, some in its plane.
      V p = random_point(rng, 2 * scale);
      if (q == 7) p = a + 0.3 * (b - a) + 0.2 * (c - a) + (b - a).cross(c - a).normalized() * 1e-3 * scale;
      if (q == 8) p = a + 1.5 * (b - a) - 0.7 * (c - a);  // in the plane, outside
      if (q == 9) p = random_point(rng, 1e3 * scale);
      check_query(p, a, b, c);
    }
    // The vertices and edge midpoints themselves.
    for (const V& p : {a, b, c, V(0.5 * (a + b)), V(0.5 * (b + c))}) check_query(p, a, b, c);
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, ClosestPointRandom, ::testing::Values(1e-3, 1.0, 1e3));

TEST(ClosestPoint, SampledDistanceAgrees) {
  // The reference itself against dense sampling: the sampled distance is an upper bound that
  // is at most the sample spacing (size / steps) above the true distance.
  std::mt19937 rng(99u);
  const int steps = 200;
  for (int t = 0; t < 40; ++t) {
    const V a = random_point(rng, 1.0), b = random_point(rng, 1.0), c = random_point(rng, 1.0);
    for (int q = 0; q < 5; ++q) {
      const V p = random_point(rng, 1.5);
      const double sampled = sampled_distance(p, a, b, c, steps);
      const double fast = (p - closest_point_on_triangle(p, a, b, c).point).norm();
      EXPECT_LE(fast, sampled + 1e-12);
      EXPECT_GE(fast, sampled - size_of(a, b, c) / steps);
    }
  }
}

// Degenerate triangles: coincident vertices, exactly collinear vertices, slivers.
struct Degenerate {
  const char* name;
  V a, b, c;
};

void PrintTo(const Degenerate& d, std::ostream* os) { *os << d.name; }

class ClosestPointDegenerate : public ::testing::TestWithParam<Degenerate> {};

TEST_P(ClosestPointDegenerate, MatchesBruteForce) {
  const Degenerate& d = GetParam();
  std::mt19937 rng(42u);
  const double size = std::max(size_of(d.a, d.b, d.c), 1.0);
  std::vector<V> queries;
  for (int q = 0; q < 2000; ++q) queries.push_back(random_point(rng, 3.0 * size));
  for (const V& p : {d.a, d.b, d.c, V(0.5 * (d.a + d.c)), V(d.a + V(0, 0, 1)), V(2.0 * d.c - d.a)})
    queries.push_back(p);

  // Exactly collinear vertices: the answer must come from the edges, never the face.
  if ((d.b - d.a).cross(d.c - d.a).isZero(0.0)) {
    for (const V& p : queries) {
      EXPECT_NE(closest_point_on_triangle(p, d.a, d.b, d.c).feature, TriangleFeature::face)
          << d.name << ", p = " << p.transpose();
    }
  }

  for (const V& p : queries) check_query(p, d.a, d.b, d.c, kSliverTol);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ClosestPointDegenerate,
    ::testing::Values(Degenerate{"all coincident", V(1, 2, 3), V(1, 2, 3), V(1, 2, 3)},
                      Degenerate{"a == b", V(0, 0, 0), V(0, 0, 0), V(1, 2, 0)},
                      Degenerate{"b == c", V(0, 0, 0), V(1, 2, 0), V(1, 2, 0)},
                      Degenerate{"c == a", V(-1, 0.5, 2), V(1, 2, 0), V(-1, 0.5, 2)},
                      Degenerate{"collinear, c beyond b", V(0, 0, 0), V(1, 1, 1), V(3, 3, 3)},
                      Degenerate{"collinear, c between", V(0, 0, 0), V(4, 2, 0), V(2, 1, 0)},
                      Degenerate{"collinear, a between", V(2, -1, 0), V(0, 0, 0), V(4, -2, 0)},
                      Degenerate{"collinear, large offset", V(1e3, 1e3, 1e3), V(1e3 + 1, 1e3 + 2, 1e3 + 3),
                                 V(1e3 + 2, 1e3 + 4, 1e3 + 6)},
                      Degenerate{"sliver", V(0, 0, 0), V(1, 0, 0), V(0.5, 1e-9, 0)},
                      Degenerate{"needle", V(0, 0, 0), V(1, 0, 0), V(1, 1e-12, 1e-12)}));

TEST(ClosestPoint, RandomSliversAndNeedles) {
  // Random triangles squashed towards a line (sliver: c near segment ab) or a point (needle:
  // b and c nearly coincident), heights from 1e-3 down to 1e-14 of the size.
  std::mt19937 rng(2718u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int t = 0; t < 300; ++t) {
    const double height = std::pow(10.0, -3.0 - 11.0 * unit(rng));
    const V a = random_point(rng, 1.0), b = random_point(rng, 1.0);
    const V off = random_point(rng, 1.0).normalized() * height;
    const V c = (t % 2 == 0) ? V(a + unit(rng) * (b - a) + off) : V(b + off);
    for (int q = 0; q < 20; ++q) check_query(random_point(rng, 2.0), a, b, c, kSliverTol);
    for (const V& p : {a, b, c}) check_query(p, a, b, c, kSliverTol);
  }
}

TEST(ClosestPoint, KnownAnswers) {
  const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const auto face = closest_point_on_triangle(V(0.2, 0.3, 5.0), a, b, c);
  EXPECT_EQ(face.feature, TriangleFeature::face);
  EXPECT_NEAR((face.point - V(0.2, 0.3, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(closest_point_on_triangle(V(-1, -1, 1), a, b, c).feature, TriangleFeature::vertex0);
  EXPECT_EQ(closest_point_on_triangle(V(2, -0.5, 0), a, b, c).feature, TriangleFeature::vertex1);
  EXPECT_EQ(closest_point_on_triangle(V(-0.1, 3, 0), a, b, c).feature, TriangleFeature::vertex2);
  const auto e01 = closest_point_on_triangle(V(0.4, -2, 1), a, b, c);
  EXPECT_EQ(e01.feature, TriangleFeature::edge01);
  EXPECT_NEAR((e01.point - V(0.4, 0, 0)).norm(), 0.0, 1e-15);
  const auto e12 = closest_point_on_triangle(V(1, 1, 0), a, b, c);
  EXPECT_EQ(e12.feature, TriangleFeature::edge12);
  EXPECT_NEAR((e12.point - V(0.5, 0.5, 0)).norm(), 0.0, 1e-15);
  const auto e20 = closest_point_on_triangle(V(-3, 0.25, -1), a, b, c);
  EXPECT_EQ(e20.feature, TriangleFeature::edge20);
  EXPECT_NEAR((e20.point - V(0, 0.25, 0)).norm(), 0.0, 1e-15);
}

TEST(ClosestPoint, SegmentParameter) {
  const V a(1, 1, 1), b(3, 1, 1);
  EXPECT_EQ(closest_parameter_on_segment(V(0, 5, 0), a, b), 0.0);
  EXPECT_EQ(closest_parameter_on_segment(V(9, 5, 0), a, b), 1.0);
  EXPECT_NEAR(closest_parameter_on_segment(V(1.5, -4, 2), a, b), 0.25, 1e-15);
  EXPECT_EQ(closest_parameter_on_segment(V(7, 7, 7), a, a), 0.0);  // zero-length segment
}

TEST(SegmentPlaneCrossing, Cases) {
  const V a(0, 0, 1), b(1, 0, 1), c(0, 1, 1);  // the plane z = 1
  // Crossing a quarter of the way; the parameter is exact up to a couple of roundings.
  auto t = segment_plane_crossing(V(0.2, 0.2, 0.0), V(0.2, 0.2, 4.0), a, b, c);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 0.25, 1e-15);
  // The plane, not the triangle: a crossing far outside the triangle still counts.
  t = segment_plane_crossing(V(50, -30, 2.0), V(50, -30, 0.0), a, b, c);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 0.5, 1e-15);
  // Ends exactly on the plane.
  t = segment_plane_crossing(V(0, 0, 1), V(0, 0, 3), a, b, c);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, 0.0);
  t = segment_plane_crossing(V(0, 0, -1), V(0, 0, 1), a, b, c);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, 1.0);
  // Short of the plane, beyond it, parallel to it, lying in it, degenerate triangle.
  EXPECT_FALSE(segment_plane_crossing(V(0, 0, 0), V(0, 0, 0.99), a, b, c).has_value());
  EXPECT_FALSE(segment_plane_crossing(V(0, 0, 1.01), V(0, 0, 5), a, b, c).has_value());
  EXPECT_FALSE(segment_plane_crossing(V(0, 0, 0), V(5, 3, 0), a, b, c).has_value());
  EXPECT_FALSE(segment_plane_crossing(V(0, 0, 1), V(5, 3, 1), a, b, c).has_value());
  EXPECT_FALSE(segment_plane_crossing(V(0, 0, 0), V(0, 0, 2), a, b, V(2, 0, 1)).has_value());
  EXPECT_FALSE(segment_plane_crossing(V(0, 0, 0), V(0, 0, 0), a, b, c).has_value());
}

TEST(SegmentPlaneCrossing, RandomCrossingsLieOnThePlane) {
  std::mt19937 rng(5u);
  int crossings = 0;
  for (int k = 0; k < 3000; ++k) {
    const V a = random_point(rng, 1.0), b = random_point(rng, 1.0), c = random_point(rng, 1.0);
    const V from = random_point(rng, 2.0), to = random_point(rng, 2.0);
    const V n = (b - a).cross(c - a).normalized();
    const double side_from = n.dot(from - a), side_to = n.dot(to - a);
    const auto t = segment_plane_crossing(from, to, a, b, c);
    // Ends on opposite sides (clearly) ⇔ a crossing; tolerance for "clearly": 1e-12 m.
    if (side_from * side_to < 0.0 && std::min(std::abs(side_from), std::abs(side_to)) > 1e-12) {
      ASSERT_TRUE(t.has_value());
      ++crossings;
      EXPECT_GE(*t, 0.0);
      EXPECT_LE(*t, 1.0);
      // The crossing point is on the plane to rounding of coordinates of order 4.
      EXPECT_NEAR(n.dot(from + *t * (to - from) - a), 0.0, 1e-13);
    } else if (side_from * side_to > 0.0 && std::min(std::abs(side_from), std::abs(side_to)) > 1e-12) {
      EXPECT_FALSE(t.has_value());
    }
  }
  EXPECT_GT(crossings, 500);
}

}  // namespace
}  // namespace fabform::closest_point_test
