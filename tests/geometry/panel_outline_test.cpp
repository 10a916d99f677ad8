// A panel's outline: its curves, checked against closed forms (Archimedes' parabolic segment,
// the circle), its arc lengths, nearest points and the loops it refuses.
#include "fabform/geometry/panel_outline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fabform/angles.hpp"

namespace fabform::panel_outline_test {
namespace {

using Vec2 = Eigen::Vector2d;

OutlineEdge straight() { return {}; }

OutlineEdge quadratic(const Vec2& c) {
  OutlineEdge e;
  e.kind = OutlineEdge::Kind::quadratic;
  e.controls = {c};
  return e;
}

OutlineEdge cubic(const Vec2& c0, const Vec2& c1) {
  OutlineEdge e;
  e.kind = OutlineEdge::Kind::cubic;
  e.controls = {c0, c1};
  return e;
}

OutlineEdge arc(double radius, bool counter_clockwise, bool large) {
  OutlineEdge e;
  e.kind = OutlineEdge::Kind::arc;
  e.radius_m = radius;
  e.counter_clockwise = counter_clockwise;
  e.large_arc = large;
  return e;
}

PanelOutline square(double side) {
  return {{{0, 0}, {side, 0}, {side, side}, {0, side}}, {straight(), straight(), straight(), straight()}};
}

// The traced polyline is inscribed in a curve of curvature κ with segments of length ≤ l: each
// segment cuts off at most (2/3)·l·(κ l²/8) of area.
double inscribed_area_error(double perimeter, double curvature, double segment) {
  return perimeter / segment * (2.0 / 3.0) * segment * curvature * segment * segment / 8.0;
}

TEST(PanelOutline, SquareAreaAndInside) {
  const TracedOutline t = trace_outline(square(0.2), 0.01);
  EXPECT_NEAR(t.signed_area(), 0.04, 1e-15);
  EXPECT_TRUE(t.contains({0.1, 0.1}));
  EXPECT_FALSE(t.contains({0.25, 0.1}));
  EXPECT_FALSE(t.contains({-0.01, 0.1}));
  for (const double length : t.edge_length) EXPECT_NEAR(length, 0.2, 1e-15);
}

TEST(PanelOutline, ClockwiseLoopHasNegativeArea) {
  PanelOutline o = square(0.2);
  std::reverse(o.vertices.begin(), o.vertices.end());
  EXPECT_NEAR(trace_outline(o, 0.01).signed_area(), -0.04, 1e-15);
}

// Archimedes: a parabolic segment is 4/3 of the triangle on its chord with the parabola's apex.
TEST(PanelOutline, QuadraticSegmentAreaIsArchimedes) {
  const PanelOutline o = {{{0, 0}, {1, 0}}, {straight(), quadratic({0.5, -1.0})}};
  // Back from (1, 0) to (0, 0) through the control (0.5, -1): the apex at t = 1/2 is 0.5 below.
  const double segment = 1e-3;
  const TracedOutline t = trace_outline(o, segment);
  const double archimedes = 4.0 / 3.0 * (0.5 * 1.0 * 0.5);
  // The parabola's curvature is largest at its apex: 2·|a| with y = a (x − ½)² − ½, a = 2.
  EXPECT_NEAR(std::abs(t.signed_area()), archimedes, inscribed_area_error(3.0, 4.0, segment));
  EXPECT_NEAR(o.point(1, 0.5).y(), -0.5, 1e-15);
}

TEST(PanelOutline, HalfDiscIsHalfTheCircle) {
  const PanelOutline o = {{{-1, 0}, {1, 0}}, {straight(), arc(1.0, true, false)}};
  const double segment = 1e-3;
  const TracedOutline t = trace_outline(o, segment);
  EXPECT_NEAR(t.signed_area(), kPi / 2, inscribed_area_error(kPi, 1.0, segment));
  EXPECT_NEAR(t.edge_length[1], kPi, kPi * segment * segment / 24.0 + 1e-12);
  EXPECT_TRUE(o.point(1, 0.5).isApprox(Vec2(0, 1), 1e-15));
}

// SVG's arc flags: the four arcs of radius 1 from (1, 0) to (0, 1) round the two centres.
TEST(PanelOutline, ArcFlagsPickCentreAndWay) {
  const PanelOutline base = {{{1, 0}, {0, 1}, {-5, -5}}, {straight(), straight(), straight()}};
  struct Case {
    bool ccw, large;
    Vec2 centre;
    Vec2 middle;
  };
  const double r = std::sqrt(0.5);
  for (const Case& c : {Case{true, false, {0, 0}, {r, r}}, Case{false, false, {1, 1}, {1 - r, 1 - r}},
                        Case{true, true, {1, 1}, {1 + r, 1 + r}}, Case{false, true, {0, 0}, {-r, -r}}}) {
    PanelOutline o = base;
    o.edges[0] = arc(1.0, c.ccw, c.large);
    for (const double t : {0.1, 0.5, 0.9}) EXPECT_NEAR((o.point(0, t) - c.centre).norm(), 1.0, 1e-14);
    EXPECT_TRUE(o.point(0, 0.5).isApprox(c.middle, 1e-14)) << c.ccw << c.large;
  }
}

// A point at arc length s lies on the curve itself and at s along it: its chord to the start is
// no longer than s, and the arc lengths at nearby points add up.
TEST(PanelOutline, PointsByArcLengthLieOnTheCurve) {
  const PanelOutline o = {{{0, 0}, {0.3, 0}, {0.3, 0.2}},
                          {cubic({0.1, -0.05}, {0.2, 0.08}), straight(), quadratic({0.0, 0.25})}};
  const TracedOutline t = trace_outline(o, 1e-4);
  for (int k = 0; k < 3; ++k) {
    const double length = t.edge_length[static_cast<std::size_t>(k)];
    EXPECT_TRUE(t.at(k, 0.0).isApprox(o.vertices[static_cast<std::size_t>(k)], 1e-15));
    EXPECT_TRUE(t.at(k, length).isApprox(o.vertices[(static_cast<std::size_t>(k) + 1) % 3], 1e-15));
    for (const double f : {0.13, 0.5, 0.77}) {
      const Vec2 p = t.at(k, f * length);
      // On the curve: the nearest of 20 000 curve points is within the spacing of those points.
      double nearest = 1e9;
      for (int i = 0; i <= 20000; ++i) nearest = std::min(nearest, (o.point(k, i / 20000.0) - p).norm());
      EXPECT_LT(nearest, 2.0 * length / 20000.0);
      EXPECT_LE((p - o.vertices[static_cast<std::size_t>(k)]).norm(), f * length * (1 + 1e-12));
      EXPECT_NEAR(t.nearest_s(k, p), f * length, 1e-6 * length);
    }
  }
}

TEST(PanelOutline, NearestPointOfAStraightEdgeIsTheProjection) {
  const TracedOutline t = trace_outline(square(0.2), 0.01);
  EXPECT_NEAR(t.nearest_s(0, {0.07, -0.03}), 0.07, 1e-15);
  EXPECT_NEAR(t.nearest_s(1, {0.25, 0.12}), 0.12, 1e-15);
  EXPECT_NEAR(t.nearest_s(0, {-0.1, 0.0}), 0.0, 1e-15);  // clamped to the edge
}

TEST(PanelOutline, RefusesWhatIsNoSimpleLoop) {
  EXPECT_EQ(square(0.2).invalid_reason(), "");
  PanelOutline two = {{{0, 0}, {1, 0}}, {straight(), straight()}};
  EXPECT_EQ(two.invalid_reason(), "an outline needs at least 3 vertices");
  PanelOutline bow = {{{0, 0}, {1, 1}, {1, 0}, {0, 1}}, {straight(), straight(), straight(), straight()}};
  EXPECT_EQ(bow.invalid_reason(), "the outline crosses itself");
  PanelOutline repeated = square(0.2);
  repeated.vertices[1] = repeated.vertices[0];
  EXPECT_EQ(repeated.invalid_reason(), "edge 0 has no length (its two vertices coincide)");
  PanelOutline controls = square(0.2);
  controls.edges[2].kind = OutlineEdge::Kind::cubic;
  EXPECT_EQ(controls.invalid_reason(), "edge 2 needs 2 control point(s)");
  PanelOutline tight = square(0.2);
  tight.edges[1] = arc(0.05, true, false);
  EXPECT_EQ(tight.invalid_reason(), "edge 1 is an arc whose radius is shorter than half the distance between its ends");
  // A curve bulging back across the outline.
  PanelOutline loop = square(0.2);
  loop.edges[0] = quadratic({0.1, 0.6});
  EXPECT_EQ(loop.invalid_reason(), "the outline crosses itself");
}

}  // namespace
}  // namespace fabform::panel_outline_test
