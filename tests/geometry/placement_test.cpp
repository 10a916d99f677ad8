// Placement: length units, scale, rotation about x then y then z, translation last.
#include "fabform/geometry/placement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace fabform::placement_test {
namespace {

using V = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;

// Rotations written out by hand (right-handed, counter-clockwise looking down the axis),
// independent of Eigen's AngleAxis.
V rot_x(const V& v, double deg) {
  const double r = deg * kPi / 180.0, c = std::cos(r), s = std::sin(r);
  return {v.x(), c * v.y() - s * v.z(), s * v.y() + c * v.z()};
}
V rot_y(const V& v, double deg) {
  const double r = deg * kPi / 180.0, c = std::cos(r), s = std::sin(r);
  return {c * v.x() + s * v.z(), v.y(), -s * v.x() + c * v.z()};
}
V rot_z(const V& v, double deg) {
  const double r = deg * kPi / 180.0, c = std::cos(r), s = std::sin(r);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()};
}

V expected_placed(const V& v, const Placement& p) {
  const V scaled = p.metres_per_unit * p.scale * v;
  return rot_z(rot_y(rot_x(scaled, p.rotation_deg.x()), p.rotation_deg.y()), p.rotation_deg.z()) +
         p.translation_m;
}

TriangleMesh tetra() {
  TriangleMesh mesh;
  mesh.vertices = {V(0, 0, 0), V(2, 0, 0), V(0, 3, 0), V(0, 0, 5), V(1.5, -2.5, 7.25)};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return mesh;
}

double signed_volume(const V& a, const V& b, const V& c, const V& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

TEST(Placement, ParseLengthUnit) {
  const std::pair<const char*, double> valid[] = {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}};
  for (const auto& [unit, metres] : valid) {
    double parsed = -1.0;
    EXPECT_TRUE(parse_length_unit(unit, &parsed)) << unit;
    EXPECT_EQ(parsed, metres) << unit;
  }
  for (const char* unit : {"", "M", "MM", "inch", "ft", " m", "m ", "um", "km", "metre"}) {
    double parsed = -1.0;
    EXPECT_FALSE(parse_length_unit(unit, &parsed)) << "'" << unit << "'";
  }
}

TEST(Placement, IdentityKeepsTheMesh) {
  const TriangleMesh mesh = tetra();
  const TriangleMesh placed = place(mesh, Placement{});
  EXPECT_EQ(placed.vertices, mesh.vertices);
  EXPECT_EQ(placed.triangles, mesh.triangles);
}

TEST(Placement, UnitAndScaleMultiply) {
  Placement p;
  p.metres_per_unit = 0.0254;
  p.scale = 2.0;
  const TriangleMesh placed = place(tetra(), p);
  for (std::size_t v = 0; v < placed.vertices.size(); ++v)
    // Two multiplications: a couple of ulps of the coordinate (≤ 0.4 m).
    EXPECT_LE((placed.vertices[v] - 0.0508 * tetra().vertices[v]).norm(), 1e-16);
}

TEST(Placement, RotationOrderIsXThenYThenZ) {
  // (0, 1, 0): x by 90° gives (0, 0, 1), then y by 90° gives (1, 0, 0). The other order
  // (y first) would give (0, 0, 1). Tolerance: cos(π/2) is 6e-17, not 0.
  TriangleMesh mesh;
  mesh.vertices = {V(0, 1, 0)};
  mesh.triangles = {{0, 0, 0}};
  Placement p;
  p.rotation_deg = V(90, 90, 0);
  EXPECT_LE((place(mesh, p).vertices[0] - V(1, 0, 0)).norm(), 1e-15);
  // Then z by 90°: (1, 0, 0) -> (0, 1, 0).
  p.rotation_deg = V(90, 90, 90);
  EXPECT_LE((place(mesh, p).vertices[0] - V(0, 1, 0)).norm(), 1e-15);
  // Each axis alone, counter-clockwise.
  p.rotation_deg = V(0, 0, 90);
  mesh.vertices = {V(1, 0, 0)};
  EXPECT_LE((place(mesh, p).vertices[0] - V(0, 1, 0)).norm(), 1e-15);
  p.rotation_deg = V(0, 90, 0);
  mesh.vertices = {V(0, 0, 1)};
  EXPECT_LE((place(mesh, p).vertices[0] - V(1, 0, 0)).norm(), 1e-15);
  p.rotation_deg = V(90, 0, 0);
  mesh.vertices = {V(0, 1, 0)};
  EXPECT_LE((place(mesh, p).vertices[0] - V(0, 0, 1)).norm(), 1e-15);
}

TEST(Placement, TranslationIsAppliedLast) {
  TriangleMesh mesh;
  mesh.vertices = {V(1, 0, 0)};
  mesh.triangles = {{0, 0, 0}};
  Placement p;
  p.scale = 3.0;
  p.rotation_deg = V(0, 0, 90);
  p.translation_m = V(10, 20, 30);
  // 3·(1,0,0) rotated to (0,3,0), then moved: the translation is neither scaled nor rotated.
  EXPECT_LE((place(mesh, p).vertices[0] - V(10, 23, 30)).norm(), 1e-13);
}

TEST(Placement, RandomPlacementsMatchHandWrittenTransform) {
  std::mt19937 rng(77u);
  std::uniform_real_distribution<double> angle(-400.0, 400.0), shift(-5.0, 5.0), scale(0.01, 10.0);
  const double units[] = {1.0, 0.01, 0.001, 0.0254};
  const TriangleMesh mesh = tetra();
  const double volume = signed_volume(mesh.vertices[0], mesh.vertices[1], mesh.vertices[2], mesh.vertices[3]);
  ASSERT_GT(volume, 0.0);
  for (int k = 0; k < 500; ++k) {
    Placement p;
    p.metres_per_unit = units[k % 4];
    p.scale = scale(rng);
    p.rotation_deg = V(angle(rng), angle(rng), angle(rng));
    p.translation_m = V(shift(rng), shift(rng), shift(rng));
    ASSERT_EQ(p.invalid_reason(), "");
    const TriangleMesh placed = place(mesh, p);
    ASSERT_EQ(placed.vertices.size(), mesh.vertices.size());
    EXPECT_EQ(placed.triangles, mesh.triangles);
    const double factor = p.metres_per_unit * p.scale;
    // Rounding of three rotations of a vector of length ≤ 9·factor plus the translation:
    // each placed coordinate is good to a few ulps of (9·factor + |t|).
    const double tol = 1e-14 * (9.0 * factor + p.translation_m.norm());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      EXPECT_LE((placed.vertices[v] - expected_placed(mesh.vertices[v], p)).norm(), tol) << k;
    // Proper rotation: lengths scale by `factor` and the tetra keeps its orientation and its
    // volume times factor³. Edges (≤ 9·factor) carry the coordinate error 2·tol, so the
    // volume (a triple product /6) is good to about 3·2·tol·(9·factor)²/6.
    const double placed_volume =
        signed_volume(placed.vertices[0], placed.vertices[1], placed.vertices[2], placed.vertices[3]);
    EXPECT_GT(placed_volume, 0.0);
    EXPECT_NEAR(placed_volume, volume * factor * factor * factor, 2.0 * tol * 81.0 * factor * factor);
    EXPECT_NEAR((placed.vertices[1] - placed.vertices[0]).norm(), 2.0 * factor, 2.0 * tol);
  }
}

TEST(Placement, InvalidReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(Placement{}.invalid_reason(), "");
  Placement ok;
  ok.scale = 1e-6;
  ok.rotation_deg = V(720, -45, 1e5);
  ok.translation_m = V(-1e3, 0, 1e3);
  EXPECT_EQ(ok.invalid_reason(), "");
  for (const double scale : {0.0, -1.0, nan, inf, -inf}) {
    Placement p;
    p.scale = scale;
    EXPECT_NE(p.invalid_reason(), "") << scale;
  }
  for (int axis = 0; axis < 3; ++axis) {
    Placement r;
    r.rotation_deg[axis] = nan;
    EXPECT_NE(r.invalid_reason(), "") << axis;
    r.rotation_deg[axis] = inf;
    EXPECT_NE(r.invalid_reason(), "") << axis;
    Placement t;
    t.translation_m[axis] = -inf;
    EXPECT_NE(t.invalid_reason(), "") << axis;
    t.translation_m[axis] = nan;
    EXPECT_NE(t.invalid_reason(), "") << axis;
  }
}

}  // namespace
}  // namespace fabform::placement_test
