// The shadow of fabrics whose projected areas are known by hand (triangles, grids flat, tilted
// and folded, a ring, a cone over a pin, a fluted drape) and the drape coefficient from it.
#include "fabform/analysis/drape_coefficient.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace fabform::drape_coefficient_test {
namespace {

using V = Eigen::Vector3d;
using Triangle = std::array<int, 3>;
constexpr double kPi = 3.14159265358979323846;

// The union is exact; only its area's final rounding to double remains (relative).
constexpr double kExact = 1e-15;
// Corners placed by sin and cos are rounded to double before the exact union (relative).
constexpr double kRoundedCorners = 1e-12;

struct Fabric {
  std::vector<V> nodes;
  std::vector<Triangle> triangles;
};

// n × m nodes over [0, width] × [0, height] at z = 0, each cell split into two triangles. The
// last column is at exactly `width` (and the last row at `height`).
Fabric grid(int n, int m, double width, double height) {
  Fabric f;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) f.nodes.emplace_back(width * (double(i) / (n - 1)), height * (double(j) / (m - 1)), 0.0);
  const auto node = [n](int i, int j) { return j * n + i; };
  for (int j = 0; j + 1 < m; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      f.triangles.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
      f.triangles.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  return f;
}

// A disc of fabric on polar rings: a centre node, then `rings` rings of `segments` nodes at
// radius r·ring/rings. `place(ρ, φ)` puts the node found at radius ρ, angle φ of the flat disc.
template <typename Place>
Fabric polar_disc(double radius, int rings, int segments, Place place) {
  Fabric f;
  f.nodes.push_back(place(0.0, 0.0));
  for (int r = 1; r <= rings; ++r)
    for (int s = 0; s < segments; ++s) f.nodes.push_back(place(radius * r / rings, 2.0 * kPi * s / segments));
  const auto node = [segments](int r, int s) { return 1 + (r - 1) * segments + s % segments; };
  for (int s = 0; s < segments; ++s) {
    f.triangles.push_back({0, node(1, s), node(1, s + 1)});
    for (int r = 1; r < rings; ++r) {
      f.triangles.push_back({node(r, s), node(r + 1, s), node(r + 1, s + 1)});
      f.triangles.push_back({node(r, s), node(r + 1, s + 1), node(r, s + 1)});
    }
  }
  return f;
}

// The area of a regular polygon of `segments` corners at `radius`.
double regular_polygon_area(double radius, int segments) {
  return 0.5 * segments * radius * radius * std::sin(2.0 * kPi / segments);
}

Shadow shadow_of(const Fabric& f) { return fabric_shadow(f.nodes, f.triangles); }

void expect_relative(double actual, double expected, double tolerance) {
  EXPECT_NEAR(actual, expected, tolerance * std::abs(expected)) << "relative error " << (actual - expected) / expected;
}

void expect_one_simple_piece(const Shadow& s) {
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.holes, 0);
  ASSERT_EQ(s.outlines.size(), 1u);
  EXPECT_EQ(static_cast<int>(s.outlines[0].size()), s.outline_vertices);
}

TEST(Shadow, OneTriangle) {
  const Shadow s = fabric_shadow({V(0, 0, 0), V(0.3, 0, 0.1), V(0, 0.2, -0.1)}, {{0, 1, 2}});
  expect_relative(s.area_m2, 0.03, kExact);
  EXPECT_EQ(s.outline_vertices, 3);
  expect_one_simple_piece(s);
}

TEST(Shadow, UnitSquareAsTwoTriangles) {
  const Shadow s = shadow_of(grid(2, 2, 1.0, 1.0));
  EXPECT_EQ(s.area_m2, 1.0);
  EXPECT_EQ(s.outline_vertices, 4);
  expect_one_simple_piece(s);
}

// The border's nodes lie on straight runs, so the outline keeps only the four corners.
TEST(Shadow, FlatGridCoversItsRectangle) {
  const Shadow s = shadow_of(grid(31, 21, 0.3, 0.2));
  expect_relative(s.area_m2, 0.3 * 0.2, kExact);
  EXPECT_EQ(s.outline_vertices, 4);
  expect_one_simple_piece(s);
}

// Turned by θ about a horizontal axis and lifted: the projection is a parallelogram of area
// W·H·|cos θ|; beyond 90° every triangle is seen from below. Turned about x, each row of nodes
// keeps one y, so the border stays exactly straight: 4 corners. Turned about an axis at 40° to
// x, the rounded border nodes leave the straight line by an ulp, which exact arithmetic sees as
// corners: the outline then has more than 4.
TEST(Shadow, LiftedTiltedGridShrinksByTheCosine) {
  const Fabric flat = grid(21, 11, 0.3, 0.2);
  for (const double axis_degrees : {0.0, 40.0})
    for (const double degrees : {30.0, 75.0, 120.0}) {
      const double theta = degrees * kPi / 180.0, phi = axis_degrees * kPi / 180.0;
      Fabric tilted = flat;
      const Eigen::AngleAxisd turn(theta, Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0));
      for (V& p : tilted.nodes) p = turn * p + V(0.05, -0.02, 0.5);
      const Shadow s = shadow_of(tilted);
      SCOPED_TRACE("axis " + std::to_string(axis_degrees) + "°, tilt " + std::to_string(degrees) + "°");
      expect_relative(s.area_m2, 0.3 * 0.2 * std::abs(std::cos(theta)), kRoundedCorners);
      if (axis_degrees == 0.0) {
        EXPECT_EQ(s.outline_vertices, 4);
      }
      expect_one_simple_piece(s);
    }
}

// Folded in half over the line x = 1 (dyadic coordinates, so the halves meet exactly): the
// folded half lies on the other, turned over, and the shadow is one half.
TEST(Shadow, GridFoldedInHalfCoversHalf) {
  Fabric f = grid(9, 5, 2.0, 1.0);
  for (V& p : f.nodes)
    if (p.x() > 1.0) p = V(2.0 - p.x(), p.y(), 0.01 * (p.x() - 1.0));
  const Shadow s = shadow_of(f);
  EXPECT_EQ(s.area_m2, 1.0);
  EXPECT_EQ(s.outline_vertices, 4);
  expect_one_simple_piece(s);
}

TEST(Shadow, DuplicateTrianglesCountOnce) {
  Fabric f = grid(2, 2, 1.0, 1.0);
  const std::vector<Triangle> once = f.triangles;
  for (const Triangle& t : once) {
    f.triangles.push_back(t);
    f.triangles.push_back({t[0], t[2], t[1]});  // the same, walked the other way round
  }
  const Shadow s = shadow_of(f);
  EXPECT_EQ(s.area_m2, 1.0);
  EXPECT_EQ(s.outline_vertices, 4);
  expect_one_simple_piece(s);
}

// Two unit squares overlapping in a quarter: 1 + 1 − 1/4, an outline of 8 corners.
TEST(Shadow, OverlappingPiecesAreJoinedNotAdded) {
  Fabric f = grid(2, 2, 1.0, 1.0);
  const Fabric moved = grid(2, 2, 1.0, 1.0);
  for (const V& p : moved.nodes) f.nodes.push_back(p + V(0.5, 0.5, 0.2));
  for (const Triangle& t : moved.triangles) f.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  const Shadow s = shadow_of(f);
  EXPECT_EQ(s.area_m2, 1.75);
  EXPECT_EQ(s.outline_vertices, 8);
  expect_one_simple_piece(s);
}

// A ring of 24 quads between regular 24-gons of radii 0.1 and 0.25 (a polar disc of two rings,
// the inner one moved out to 0.1, without its centre): the area between the 24-gons.
TEST(Shadow, RingHasOneHole) {
  const int segments = 24;
  const double inner = 0.1, outer = 0.25;
  Fabric f = polar_disc(outer, 2, segments, [&](double rho, double phi) {
    const double r = rho == 0.0 ? 0.0 : (rho < outer ? inner : outer);
    return V(r * std::cos(phi), r * std::sin(phi), 0.0);
  });
  f.triangles.erase(std::remove_if(f.triangles.begin(), f.triangles.end(),
                                   [](const Triangle& t) { return t[0] == 0; }),  // the centre's fan
                    f.triangles.end());
  ASSERT_EQ(f.triangles.size(), 2u * segments);
  const Shadow s = shadow_of(f);
  expect_relative(s.area_m2, regular_polygon_area(outer, segments) - regular_polygon_area(inner, segments),
                  kRoundedCorners);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.holes, 1);
  EXPECT_EQ(s.outline_vertices, segments);
}

TEST(Shadow, SeparatePiecesAreComponents) {
  Fabric f = grid(3, 3, 1.0, 1.0);
  const Fabric apart = grid(2, 2, 0.5, 0.5);
  for (const V& p : apart.nodes) f.nodes.push_back(p + V(2.0, 0.0, 0.0));
  for (const Triangle& t : apart.triangles) f.triangles.push_back({t[0] + 9, t[1] + 9, t[2] + 9});
  const Shadow s = shadow_of(f);
  EXPECT_EQ(s.area_m2, 1.25);
  EXPECT_EQ(s.components, 2);
  EXPECT_EQ(s.holes, 0);
  EXPECT_EQ(s.outline_vertices, 8);
}

// Squares touching at one corner only: CGAL keeps them one piece, its outline passing twice
// through the shared corner.
TEST(Shadow, PiecesMeetingAtAPointAreOne) {
  const Shadow s = fabric_shadow({V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0), V(2, 1, 0), V(2, 2, 0), V(1, 2, 0)},
                                 {{0, 1, 2}, {0, 2, 3}, {2, 4, 5}, {2, 5, 6}});
  EXPECT_EQ(s.area_m2, 2.0);
  EXPECT_EQ(s.outline_vertices, 8);
  expect_one_simple_piece(s);
}

TEST(Shadow, TriangleSeenEdgeOnCastsNone) {
  const std::vector<V> nodes = {V(0, 0, 0), V(1, 0, 0), V(0, 0, 1), V(0, 1, 0)};
  const Shadow alone = fabric_shadow(nodes, {{0, 1, 2}});
  EXPECT_EQ(alone.area_m2, 0.0);
  EXPECT_EQ(alone.components, 0);
  EXPECT_EQ(alone.outline_vertices, 0);
  EXPECT_TRUE(alone.outlines.empty());

  const Shadow with_flat = fabric_shadow(nodes, {{0, 1, 2}, {0, 1, 3}, {0, 0, 1}});  // and a repeated node
  EXPECT_EQ(with_flat.area_m2, 0.5);
  expect_one_simple_piece(with_flat);
}

TEST(Shadow, NoTrianglesNoShadow) {
  const Shadow s = fabric_shadow({V(0, 0, 0)}, {});
  EXPECT_EQ(s.area_m2, 0.0);
  EXPECT_EQ(s.components, 0);
}

// A disc of radius r draped as a cone over a pin, sloping down at α: every point moves in
// to ρ·cos α, so the shadow is the fabric's outer 48-gon shrunk by cos α, and DC = cos² α.
TEST(Shadow, ConeOverAPinIsTheDiscShrunkByTheCosine) {
  const int segments = 48;
  const double radius = 0.15, alpha = 35.0 * kPi / 180.0;
  const Fabric cone = polar_disc(radius, 10, segments, [&](double rho, double phi) {
    return V(rho * std::cos(alpha) * std::cos(phi), rho * std::cos(alpha) * std::sin(phi), 0.3 - rho * std::sin(alpha));
  });
  const Shadow s = shadow_of(cone);
  const double specimen_m2 = regular_polygon_area(radius, segments);
  expect_relative(s.area_m2, regular_polygon_area(radius * std::cos(alpha), segments), kRoundedCorners);
  EXPECT_EQ(s.outline_vertices, segments);
  expect_one_simple_piece(s);
  EXPECT_NEAR(drape_coefficient(s.area_m2, specimen_m2, 0.0), std::pow(std::cos(alpha), 2), 1e-12);
}

// Cusick-like: flat on a disc of radius 0.09, then hanging in 7 folds, the overhang reaching
// out 0.6 ± 0.3 of its flat length. The shadow's outline shows the 7 folds.
TEST(Shadow, FlutedDrapeShowsItsFolds) {
  const int folds = 7, segments = 12 * folds;
  const double disc = 0.09, radius = 0.15;
  const Fabric drape = polar_disc(radius, 10, segments, [&](double rho, double phi) {
    const double out = rho <= disc ? rho : disc + (rho - disc) * (0.6 + 0.3 * std::cos(folds * phi));
    return V(out * std::cos(phi), out * std::sin(phi), -std::max(0.0, rho - disc));
  });
  const Shadow s = shadow_of(drape);
  expect_one_simple_piece(s);
  EXPECT_EQ(s.outline_vertices, segments);
  EXPECT_EQ(count_folds(s.outlines[0], Eigen::Vector2d::Zero()), folds);
  EXPECT_EQ(count_folds(s.outlines[0], Eigen::Vector2d::Zero(), 1e-3), folds);
  const double dc = drape_coefficient(s.area_m2, kPi * radius * radius, kPi * disc * disc);
  EXPECT_GT(dc, 0.0);
  EXPECT_LT(dc, 1.0);
}

TEST(Shadow, FlatDiscHasNoFolds) {
  const Shadow s = shadow_of(polar_disc(0.15, 4, 60, [](double rho, double phi) {
    return V(rho * std::cos(phi), rho * std::sin(phi), 0.0);
  }));
  // Rounded corners wobble by an ulp round the circle; a depth of a nanometre ignores that.
  EXPECT_EQ(count_folds(s.outlines[0], Eigen::Vector2d::Zero(), 1e-9), 0);
}

TEST(Shadow, FoldsOfTooShortAnOutlineAreNone) {
  EXPECT_EQ(count_folds({}, Eigen::Vector2d::Zero()), 0);
  EXPECT_EQ(count_folds({Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 2)}, Eigen::Vector2d::Zero()), 0);
}

// Four lobes, then a depth larger than the lobes hides them; a negative depth is an error.
TEST(Shadow, FoldsAreCountedAboveTheirDepth) {
  std::vector<Eigen::Vector2d> outline;
  for (int k = 0; k < 64; ++k) {
    const double phi = 2.0 * kPi * k / 64, r = 0.1 + 0.01 * std::cos(4.0 * phi);
    outline.emplace_back(r * std::cos(phi), r * std::sin(phi));
  }
  EXPECT_EQ(count_folds(outline, Eigen::Vector2d::Zero(), 0.0), 4);
  EXPECT_EQ(count_folds(outline, Eigen::Vector2d::Zero(), 0.019), 4);
  EXPECT_EQ(count_folds(outline, Eigen::Vector2d::Zero(), 0.021), 0);
  EXPECT_THROW(count_folds(outline, Eigen::Vector2d::Zero(), -1e-3), std::invalid_argument);
}

// Exact arithmetic: the union of a crumpled grid is the same whatever order its triangles
// come in, bounded by the largest triangle and by the sum of all.
TEST(Shadow, CrumpledGridAreaDoesNotDependOnOrder) {
  Fabric f = grid(15, 15, 0.1, 0.1);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jiggle(-0.01, 0.01);
  for (V& p : f.nodes) p += V(jiggle(random), jiggle(random), jiggle(random));
  const Shadow first = shadow_of(f);
  std::shuffle(f.triangles.begin(), f.triangles.end(), random);
  for (Triangle& t : f.triangles) std::rotate(t.begin(), t.begin() + 1, t.end());
  EXPECT_EQ(shadow_of(f).area_m2, first.area_m2);

  double sum = 0.0, largest = 0.0;
  for (const Triangle& t : f.triangles) {
    const V a = f.nodes[t[0]], b = f.nodes[t[1]], c = f.nodes[t[2]];
    const double area = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    sum += area, largest = std::max(largest, area);
  }
  EXPECT_GT(first.area_m2, largest);
  EXPECT_LT(first.area_m2, sum);
}

TEST(Shadow, NonFinitePositionThrowsNamingTheNode) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const V& bad : {V(nan, 0, 0), V(0, 0, inf)}) {
    Fabric f = grid(3, 3, 1.0, 1.0);
    f.nodes[4] = bad;
    try {
      shadow_of(f);
      ADD_FAILURE() << "no throw";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("node 4 "), std::string::npos) << e.what();
    }
  }
}

TEST(Shadow, TriangleNamingAMissingNodeThrows) {
  EXPECT_THROW(fabric_shadow({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {{0, 1, 3}}), std::invalid_argument);
  EXPECT_THROW(fabric_shadow({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {{-1, 1, 2}}), std::invalid_argument);
}

TEST(DrapeCoefficient, FlatSpecimenIsOne) {
  EXPECT_EQ(drape_coefficient(0.0707, 0.0707, 0.0254), 1.0);
  EXPECT_EQ(drape_coefficient(0.0707, 0.0707, 0.0), 1.0);
}

TEST(DrapeCoefficient, ShadowOfTheDiscAloneIsZero) {
  EXPECT_EQ(drape_coefficient(0.0254, 0.0707, 0.0254), 0.0);
}

TEST(DrapeCoefficient, IsTheShareOfTheOverhangSeen) {
  EXPECT_DOUBLE_EQ(drape_coefficient(0.05, 0.09, 0.01), 0.5);
}

TEST(DrapeCoefficient, BadAreasThrow) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(drape_coefficient(-0.01, 0.07, 0.02), std::invalid_argument);
  EXPECT_THROW(drape_coefficient(0.05, 0.07, -0.02), std::invalid_argument);
  EXPECT_THROW(drape_coefficient(nan, 0.07, 0.02), std::invalid_argument);
  EXPECT_THROW(drape_coefficient(0.05, inf, 0.02), std::invalid_argument);
  EXPECT_THROW(drape_coefficient(0.05, 0.07, nan), std::invalid_argument);
  EXPECT_THROW(drape_coefficient(0.05, 0.02, 0.02), std::invalid_argument);  // no overhang
  EXPECT_THROW(drape_coefficient(0.05, 0.01, 0.02), std::invalid_argument);
  try {
    drape_coefficient(0.05, 0.01, 0.02);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("larger than the disc"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fabform::drape_coefficient_test
