// Initial shapes: flat, lift, bump, wrap, tube and fold positions, and which parameters are rejected.
#include "fabform/fabric/initial_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace fabform::initial_shape_test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();

using Kind = InitialShape::Kind;

InitialShape shape_of(Kind kind, double height = 0.0) {
  InitialShape shape;
  shape.kind = kind;
  shape.height_m = height;
  return shape;
}

// Even divisions, so there is a centre node at (W/2, H/2).
const FabricSpec kSpec{0.4, 0.3, 8, 6};
const Eigen::Vector3d kOrigin(0.25, -0.5, 1.2);
// Coordinates are sums of numbers of order 1 m: a few ulps of that.
const double kTol = 8 * kEps * 2.0;

TEST(InitialShape, FlatIsTheRestGridAtTheOrigin) {
  const Fabric grid(kSpec);
  const auto x = initial_positions(grid, kOrigin, shape_of(Kind::flat));
  ASSERT_EQ(x.size(), static_cast<std::size_t>(grid.node_count()));
  for (int k = 0; k < grid.node_count(); ++k)
    EXPECT_LE((x[static_cast<std::size_t>(k)] - (kOrigin + grid.rest_position(k))).norm(), kTol);
  // Flat ignores height_m.
  const auto y = initial_positions(grid, kOrigin, shape_of(Kind::flat, 0.7));
  EXPECT_EQ(x, y);
}

TEST(InitialShape, LiftRaisesOnlyInteriorNodes) {
  const Fabric grid(kSpec);
  for (const double h : {0.05, -0.02}) {
    const auto x = initial_positions(grid, kOrigin, shape_of(Kind::lift, h));
    for (int k = 0; k < grid.node_count(); ++k) {
      const Eigen::Vector3d flat = kOrigin + grid.rest_position(k);
      const Eigen::Vector3d& p = x[static_cast<std::size_t>(k)];
      EXPECT_NEAR(p.x(), flat.x(), kTol);
      EXPECT_NEAR(p.y(), flat.y(), kTol);
      EXPECT_NEAR(p.z(), kOrigin.z() + (grid.on_perimeter(k) ? 0.0 : h), kTol) << k;
    }
  }
}

TEST(InitialShape, BumpIsZeroOnPerimeterAndPeaksAtCentre) {
  const Fabric grid(kSpec);
  const double h = 0.08;
  const auto x = initial_positions(grid, kOrigin, shape_of(Kind::bump, h));
  const int centre = grid.node(4, 3);
  double highest = -1.0;
  int highest_node = -1;
  for (int k = 0; k < grid.node_count(); ++k) {
    const Eigen::Vector3d flat = kOrigin + grid.rest_position(k);
    const Eigen::Vector3d& p = x[static_cast<std::size_t>(k)];
    EXPECT_NEAR(p.x(), flat.x(), kTol);
    EXPECT_NEAR(p.y(), flat.y(), kTol);
    const double lift = p.z() - kOrigin.z();
    // sin(π) is 1.2e-16, not 0: the perimeter is zero to a few ulps of the height.
    if (grid.on_perimeter(k)) EXPECT_NEAR(lift, 0.0, kTol) << k;
    else EXPECT_GT(lift, 0.0) << k;
    // The product of two half sines, independently of the implementation.
    const Eigen::Vector3d r = grid.rest_position(k);
    EXPECT_NEAR(lift, h * std::sin(kPi * r.x() / kSpec.width_m) * std::sin(kPi * r.y() / kSpec.height_m),
                kTol);
    if (lift > highest) highest = lift, highest_node = k;
  }
  EXPECT_EQ(highest_node, centre);
  EXPECT_NEAR(highest, h, kTol);
  // Symmetric about the centre lines.
  for (int j = 0; j < grid.nodes_weft(); ++j)
    for (int i = 0; i < grid.nodes_warp(); ++i)
      EXPECT_NEAR(x[static_cast<std::size_t>(grid.node(i, j))].z(),
                  x[static_cast<std::size_t>(grid.node(grid.nodes_warp() - 1 - i, grid.nodes_weft() - 1 - j))].z(),
                  kTol);
}

struct WrapCase {
  double radius, facing_deg, span_deg;
  Eigen::Vector2d axis;
};

class InitialShapeWrap : public ::testing::TestWithParam<WrapCase> {};

TEST_P(InitialShapeWrap, OnCylinderWithWeftAlongZ) {
  const WrapCase c = GetParam();
  const Fabric grid(kSpec);
  InitialShape shape = shape_of(Kind::wrap);
  shape.radius_m = c.radius;
  shape.facing_deg = c.facing_deg;
  shape.span_deg = c.span_deg;
  shape.axis_xy_m = c.axis;
  ASSERT_EQ(shape.invalid_reason(), "");
  const auto x = initial_positions(grid, kOrigin, shape);
  // Tolerance: coordinates are R·cos/sin plus the axis, a few ulps of |axis| + R.
  const double tol = 16 * kEps * (c.radius + c.axis.norm() + 2.0);
  for (int k = 0; k < grid.node_count(); ++k) {
    const Eigen::Vector3d& p = x[static_cast<std::size_t>(k)];
    EXPECT_NEAR((p.head<2>() - c.axis).norm(), c.radius, tol) << k;
    // Weft vertical, starting at the origin's z, with the rest spacing.
    EXPECT_NEAR(p.z(), kOrigin.z() + grid.rest_position(k).y(), tol) << k;
  }
  for (int j = 0; j < grid.nodes_weft(); ++j) {
    // Walk a warp row: angles increase by span/(n−1) each step; the arc is R·span.
    double arc = 0.0, chords = 0.0;
    for (int i = 0; i + 1 < grid.nodes_warp(); ++i) {
      const Eigen::Vector3d& p = x[static_cast<std::size_t>(grid.node(i, j))];
      const Eigen::Vector3d& q = x[static_cast<std::size_t>(grid.node(i + 1, j))];
      const Eigen::Vector2d u = p.head<2>() - c.axis, v = q.head<2>() - c.axis;
      const double step = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));  // signed, ccw
      EXPECT_GT(step, 0.0);
      arc += c.radius * step;
      chords += (q - p).norm();
      EXPECT_NEAR(q.z(), p.z(), tol);  // a warp row stays level
    }
    const double span = c.span_deg * kPi / 180.0;
    // atan2 of nearly unit vectors: relative 1e-12 of the arc.
    EXPECT_NEAR(arc, c.radius * span, 1e-12 * c.radius * span + tol);
    const int segments = grid.nodes_warp() - 1;
    EXPECT_NEAR(chords, segments * 2.0 * c.radius * std::sin(span / (2.0 * segments)), 1e-12 * c.radius * span + tol);
    // The middle node faces facing_deg.
    const Eigen::Vector3d& mid = x[static_cast<std::size_t>(grid.node(segments / 2, j))];
    const double facing = c.facing_deg * kPi / 180.0;
    EXPECT_NEAR(mid.x(), c.axis.x() + c.radius * std::cos(facing), tol);
    EXPECT_NEAR(mid.y(), c.axis.y() + c.radius * std::sin(facing), tol);
  }
  // The weft spacing is kept along z: neighbouring nodes in a column are H/(m−1) apart.
  for (int i = 0; i < grid.nodes_warp(); ++i)
    for (int j = 0; j + 1 < grid.nodes_weft(); ++j)
      EXPECT_NEAR((x[static_cast<std::size_t>(grid.node(i, j + 1))] - x[static_cast<std::size_t>(grid.node(i, j))]).norm(),
                  grid.spacing_weft(), tol);
}

INSTANTIATE_TEST_SUITE_P(Cases, InitialShapeWrap,
                         ::testing::Values(WrapCase{0.15, 0.0, 120.0, {0.0, 0.0}},
                                           WrapCase{0.2, 90.0, 200.0, {0.3, -0.1}},
                                           WrapCase{1.0, -45.0, 359.0, {-2.0, 5.0}},
                                           WrapCase{0.05, 270.0, 1.0, {0.0, 0.0}}));

TEST(InitialShape, InvalidReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto wrap = [](double radius, double span) {
    InitialShape s = shape_of(Kind::wrap);
    s.radius_m = radius;
    s.span_deg = span;
    return s;
  };
  // Valid.
  EXPECT_EQ(shape_of(Kind::flat).invalid_reason(), "");
  EXPECT_EQ(shape_of(Kind::flat, 0.3).invalid_reason(), "");
  EXPECT_EQ(shape_of(Kind::lift, 0.02).invalid_reason(), "");
  EXPECT_EQ(shape_of(Kind::lift, -0.02).invalid_reason(), "");  // pushed down is allowed
  EXPECT_EQ(shape_of(Kind::bump, 0.1).invalid_reason(), "");
  EXPECT_EQ(wrap(0.1, 180.0).invalid_reason(), "");
  EXPECT_EQ(wrap(0.1, 359.9).invalid_reason(), "");
  // Invalid.
  EXPECT_NE(shape_of(Kind::lift, 0.0).invalid_reason(), "");
  EXPECT_NE(shape_of(Kind::bump, 0.0).invalid_reason(), "");
  EXPECT_NE(shape_of(Kind::lift, nan).invalid_reason(), "");
  EXPECT_NE(shape_of(Kind::flat, inf).invalid_reason(), "");
  EXPECT_NE(wrap(0.0, 180.0).invalid_reason(), "");
  EXPECT_NE(wrap(-0.1, 180.0).invalid_reason(), "");
  EXPECT_NE(wrap(nan, 180.0).invalid_reason(), "");
  EXPECT_NE(wrap(0.1, 0.0).invalid_reason(), "");
  EXPECT_NE(wrap(0.1, -30.0).invalid_reason(), "");
  EXPECT_NE(wrap(0.1, 360.0).invalid_reason(), "");
  EXPECT_NE(wrap(0.1, 720.0).invalid_reason(), "");
  EXPECT_NE(wrap(0.1, inf).invalid_reason(), "");
  InitialShape bad_axis = wrap(0.1, 90.0);
  bad_axis.axis_xy_m.y() = nan;
  EXPECT_NE(bad_axis.invalid_reason(), "");
  InitialShape bad_facing = wrap(0.1, 90.0);
  bad_facing.facing_deg = -inf;
  EXPECT_NE(bad_facing.invalid_reason(), "");
}

TEST(InitialShape, ParseKind) {
  const std::pair<const char*, Kind> valid[] = {
      {"flat", Kind::flat}, {"lift", Kind::lift}, {"bump", Kind::bump}, {"wrap", Kind::wrap}};
  for (const auto& [name, kind] : valid) {
    Kind parsed = Kind::flat;
    EXPECT_TRUE(parse_initial_kind(name, &parsed)) << name;
    EXPECT_EQ(parsed, kind);
  }
  for (const char* name : {"", "Flat", "wrapped", " lift", "cylinder"}) {
    Kind parsed = Kind::flat;
    EXPECT_FALSE(parse_initial_kind(name, &parsed)) << name;
  }
}

// A tube starts once round its axis: every node on the circle, its two seam edges on one another,
// its length vertical from the origin's height; the warp round it or along it.
TEST(InitialShape, ATubeGoesOnceRoundItsAxisWithItsSeamClosed) {
  for (const FabricSpec::Tube tube : {FabricSpec::Tube::warp_round, FabricSpec::Tube::warp_along}) {
    FabricSpec spec = kSpec;
    spec.tube = tube;
    const Fabric grid(spec);
    InitialShape shape = shape_of(Kind::tube);
    shape.axis_xy_m = Eigen::Vector2d(0.1, -0.2);
    shape.radius_m = 0.07;
    shape.facing_deg = 30.0;
    const auto x = initial_positions(grid, kOrigin, shape);
    const bool round_warp = tube == FabricSpec::Tube::warp_round;
    for (int k = 0; k < grid.node_count(); ++k) {
      const Eigen::Vector3d& p = x[static_cast<std::size_t>(k)];
      EXPECT_NEAR((p.head<2>() - shape.axis_xy_m).norm(), 0.07, kTol);
      const Eigen::Vector3d flat = grid.rest_position(k);
      EXPECT_NEAR(p.z(), kOrigin.z() + (round_warp ? flat.y() : flat.x()), kTol);
    }
    const int last = round_warp ? grid.nodes_warp() - 1 : grid.nodes_weft() - 1;
    for (int along = 0; along < (round_warp ? grid.nodes_weft() : grid.nodes_warp()); ++along) {
      const int first = round_warp ? grid.node(0, along) : grid.node(along, 0);
      const int other = round_warp ? grid.node(last, along) : grid.node(along, last);
      EXPECT_LE((x[static_cast<std::size_t>(first)] - x[static_cast<std::size_t>(other)]).norm(), 1e-15);
      // The seam faces facing_deg.
      const Eigen::Vector2d facing(std::cos(30.0 * kPi / 180.0), std::sin(30.0 * kPi / 180.0));
      EXPECT_NEAR((x[static_cast<std::size_t>(first)].head<2>() - shape.axis_xy_m).normalized().dot(facing), 1.0, 1e-12);
    }
  }
}

// A fold lays the part beyond the line back over the part before it, height_m above.
TEST(InitialShape, AFoldMirrorsThePartBeyondTheLineOnTop) {
  const Fabric grid(kSpec);
  InitialShape shape = shape_of(Kind::fold, 0.004);
  shape.fold_at_m = 0.25;
  const auto x = initial_positions(grid, kOrigin, shape);
  for (int k = 0; k < grid.node_count(); ++k) {
    const Eigen::Vector3d flat = grid.rest_position(k);
    const bool beyond = flat.x() > 0.25;
    const Eigen::Vector3d expected =
        kOrigin + Eigen::Vector3d(beyond ? 0.5 - flat.x() : flat.x(), flat.y(), beyond ? 0.004 : 0.0);
    EXPECT_LE((x[static_cast<std::size_t>(k)] - expected).norm(), kTol) << k;
  }
  std::string field;
  shape.fold_at_m = 0.0;
  EXPECT_NE(shape.invalid_reason(&field), "");
  EXPECT_EQ(field, "fold_at_m");
  EXPECT_NE(shape_of(Kind::fold, 0.0).invalid_reason(&field), "");
}

TEST(InitialShape, ATubeNeedsThreeDivisionsRoundItAndARectangle) {
  FabricSpec spec = kSpec;
  spec.tube = FabricSpec::Tube::warp_round;
  spec.divisions_warp = 2;
  EXPECT_NE(spec.invalid_reason(), "");
  spec.tube = FabricSpec::Tube::warp_along;
  EXPECT_EQ(spec.invalid_reason(), "");  // 6 weft divisions round it
  spec.shape = FabricSpec::Shape::circle;
  spec.width_m = spec.height_m;
  spec.divisions_warp = spec.divisions_weft;
  EXPECT_NE(spec.invalid_reason().find("tube"), std::string::npos) << spec.invalid_reason();
}

}  // namespace
}  // namespace fabform::initial_shape_test
