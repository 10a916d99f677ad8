// RigidBody: BVH closest-point queries against a brute-force loop on the shipped meshes,
// signed distance and first entry on hand-made boxes, and on a real mesh against brute force.
#include "fabform/geometry/rigid_body.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "fabform/geometry/closest_point.hpp"
#include "fabform/geometry/placement.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "support/shapes.hpp"
#include "test_paths.hpp"

namespace fabform::rigid_body_test {
namespace {

using V = Eigen::Vector3d;

// ---------------------------------------------------------------------------------------------
// Brute force and helpers

struct Brute {
  double distance = std::numeric_limits<double>::infinity();
  int triangle = -1;
};

Brute brute_closest(const TriangleMesh& mesh, const V& p) {
  Brute best;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const V q = closest_point_on_triangle(p, mesh.vertices[static_cast<std::size_t>(tri[0])],
                                          mesh.vertices[static_cast<std::size_t>(tri[1])],
                                          mesh.vertices[static_cast<std::size_t>(tri[2])])
                    .point;
    const double d = (p - q).norm();
    if (d < best.distance) best = {d, static_cast<int>(t)};
  }
  return best;
}

const V& vertex(const TriangleMesh& mesh, int triangle, int corner) {
  return mesh.vertices[static_cast<std::size_t>(
      mesh.triangles[static_cast<std::size_t>(triangle)][static_cast<std::size_t>(corner)])];
}

// Segment–triangle intersection in double (Möller–Trumbore): parameter t along from→to and
// the smallest barycentric coordinate (how far inside the triangle the hit is).
struct Crossing {
  double t;
  double margin;
  bool front;  // crossing from outside to inside (against the outward face normal)
};

std::vector<Crossing> brute_crossings(const TriangleMesh& mesh, const V& from, const V& to) {
  std::vector<Crossing> hits;
  const V dir = to - from;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const V& a = vertex(mesh, t, 0);
    const V e1 = vertex(mesh, t, 1) - a, e2 = vertex(mesh, t, 2) - a;
    const V pvec = dir.cross(e2);
    const double det = e1.dot(pvec);
    if (det == 0.0) continue;
    const V tvec = from - a;
    const double u = tvec.dot(pvec) / det;
    const V qvec = tvec.cross(e1);
    const double v = dir.dot(qvec) / det;
    const double s = e2.dot(qvec) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0 || s < 0.0 || s > 1.0) continue;
    hits.push_back({s, std::min({u, v, 1.0 - u - v}), e1.cross(e2).dot(dir) < 0.0});
  }
  std::sort(hits.begin(), hits.end(), [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
  return hits;
}

double distance_to_segment(const V& p, const V& a, const V& b) {
  const double t = closest_parameter_on_segment(p, a, b);
  return (p - (a + t * (b - a))).norm();
}

// An axis-aligned box with outward-facing triangles, centred at `centre`.
void append_box(TriangleMesh* mesh, const V& centre, const V& half) {
  const int base = static_cast<int>(mesh->vertices.size());
  for (int k = 0; k < 8; ++k)
    mesh->vertices.push_back(centre + V((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(),
                                        (k & 4) ? half.z() : -half.z()));
  // Faces as quads (counter-clockwise seen from outside), split into two triangles.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    mesh->triangles.push_back({base + q[0], base + q[1], base + q[2]});
    mesh->triangles.push_back({base + q[0], base + q[2], base + q[3]});
  }
}

// Exact signed distance to an axis-aligned box of half extents h at the origin.
double box_signed_distance(const V& p, const V& h) {
  const V q = p.cwiseAbs() - h;
  const double outside = q.cwiseMax(0.0).norm();
  const double inside = std::min(q.maxCoeff(), 0.0);
  return outside + inside;
}

double signed_volume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    volume += vertex(mesh, t, 0).dot(vertex(mesh, t, 1).cross(vertex(mesh, t, 2))) / 6.0;
  return volume;
}

// ---------------------------------------------------------------------------------------------
// Real meshes, loaded once.

struct RealMesh {
  std::string name;
  std::unique_ptr<RigidBody> body;
};

class RigidBodyRealMeshes : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    Placement inches;
    inches.metres_per_unit = 0.0254;
    featuretype_ = new RealMesh{"featuretype", std::make_unique<RigidBody>(
        "featuretype", place(read_mesh(test::source_path("molds/trimesh_featuretype.STL")), inches))};
    torso_ = new RealMesh{"torso_open", std::make_unique<RigidBody>(
        "torso_open", read_mesh(test::source_path("molds/garmentcode_mean_female_torso_open.obj")))};
  }
  static void TearDownTestSuite() {
    delete featuretype_;
    delete torso_;
    featuretype_ = torso_ = nullptr;
  }

  // Query points: uniform around the box, on the surface, just off it, at mesh vertices and
  // far away.
  static std::vector<V> query_points(const RigidBody& body, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const TriangleMesh& mesh = body.mesh();
    const BoundingBox box = body.box();
    const double diag = box.diagonal();
    const V lo = box.min - V::Constant(0.25 * diag), hi = box.max + V::Constant(0.25 * diag);
    std::vector<V> points;
    for (int k = 0; k < 1000; ++k)
      points.push_back(lo + (hi - lo).cwiseProduct(V(unit(rng), unit(rng), unit(rng))));
    const int triangles = static_cast<int>(mesh.triangles.size());
    for (int k = 0; k < 1600; ++k) {
      const int t = std::min(static_cast<int>(unit(rng) * triangles), triangles - 1);
      double u = unit(rng), v = unit(rng);
      if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
      const V on = vertex(mesh, t, 0) + u * (vertex(mesh, t, 1) - vertex(mesh, t, 0)) +
                   v * (vertex(mesh, t, 2) - vertex(mesh, t, 0));
      if (k % 2 == 0) points.push_back(on);  // on the surface
      else points.push_back(on + (2.0 * unit(rng) - 1.0) * 1e-3 * diag * body.face_normal(t));
    }
    std::uniform_int_distribution<std::size_t> any_vertex(0, mesh.vertices.size() - 1);
    for (int k = 0; k < 200; ++k) points.push_back(mesh.vertices[any_vertex(rng)]);
    for (int k = 0; k < 200; ++k) {
      const V direction = V(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
      points.push_back(0.5 * (box.min + box.max) + std::pow(10.0, 1.0 + 2.0 * unit(rng)) * diag * direction);
    }
    return points;
  }

  static void check_closest_against_brute_force(const RigidBody& body, unsigned seed) {
    const TriangleMesh& mesh = body.mesh();
    // Embree's BVH is float: its boxes may cull or admit a triangle wrongly by ~1e-7 of the
    // coordinates, which RigidBody::closest covers with a margin; the double narrow phase
    // then decides. Two triangles at the same double distance may be swapped, never a
    // different distance by more than the margin: 1e-9 m + 1e-6 × the box diagonal.
    const double tol = 1e-9 + 1e-6 * body.box().diagonal();
    int mismatches = 0;
    for (const V& p : query_points(body, seed)) {
      const SurfacePoint s = body.closest(p);
      const Brute brute = brute_closest(mesh, p);
      ASSERT_GE(s.triangle, 0);
      ASSERT_LT(s.triangle, static_cast<int>(mesh.triangles.size()));
      mismatches += std::abs(s.distance - brute.distance) > tol;
      EXPECT_NEAR(s.distance, brute.distance, tol) << "p " << p.transpose() << " triangle " << s.triangle
                                                    << " vs brute " << brute.triangle;
      // The answer is self-consistent: the point is on its triangle, the distances agree.
      EXPECT_NEAR((p - s.point).norm(), s.distance, 1e-12 * (1.0 + s.distance));
      EXPECT_NEAR(std::abs(s.signed_distance), s.distance, 1e-15);
      const V on_triangle = closest_point_on_triangle(p, vertex(mesh, s.triangle, 0), vertex(mesh, s.triangle, 1),
                                                      vertex(mesh, s.triangle, 2))
                                .point;
      EXPECT_LE((on_triangle - s.point).norm(), 1e-12 * body.box().diagonal());
      EXPECT_NEAR(s.normal.norm(), 1.0, 1e-12);
      if (mismatches > 10) FAIL() << "too many mismatches";
    }
  }

  static void check_closest_within_against_brute_force(const RigidBody& body, unsigned seed) {
    // closest_within(p, r) answers iff the surface is within r of p, and then as closest().
    // Radii around the true distance d are left out within a band where float culling may
    // decide either way: the margin above, plus the rounding of p and r themselves, which
    // Embree receives as floats (half a float ulp each, relative to |p| and r; this matters
    // for the far-away points, 10–1000 diagonals out).
    const double tol = 1e-9 + 1e-6 * body.box().diagonal();
    const double float_eps = static_cast<double>(std::numeric_limits<float>::epsilon());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<V> points = query_points(body, seed);
    for (std::size_t k = 0; k < points.size(); k += 3) {
      const V& p = points[k];
      const double d = brute_closest(body.mesh(), p).distance;
      const double band = tol + 2.0 * float_eps * (p.norm() + d);
      for (const double r : {0.0, 0.5 * d, d - 2.0 * band, d + 2.0 * band, 2.0 * d + band,
                             1e3 * body.box().diagonal(), std::numeric_limits<double>::infinity(),
                             unit(rng) * 2.0 * d}) {
        if (r < 0.0 || std::abs(r - d) <= band) continue;
        const auto found = body.closest_within(p, r);
        if (d <= r) {
          ASSERT_TRUE(found.has_value()) << "p " << p.transpose() << " d " << d << " r " << r;
          EXPECT_NEAR(found->distance, d, band);
          EXPECT_LE(found->distance, r);
        } else {
          EXPECT_FALSE(found.has_value()) << "p " << p.transpose() << " d " << d << " r " << r;
        }
      }
    }
  }

  static void check_hinted_closest_against_brute_force(const RigidBody& body, unsigned seed) {
    // closest(p, t) answers as closest(p) whatever triangle t hints: none (-1), one past the
    // last, a random one (often far), or the answer itself. Ties between triangles at the same
    // distance may name either, with the same point, distance and side.
    const double tol = 1e-9 + 1e-6 * body.box().diagonal();
    const int triangles = static_cast<int>(body.mesh().triangles.size());
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> any_triangle(0, triangles - 1);
    const std::vector<V> points = query_points(body, seed);
    for (std::size_t k = 0; k < points.size(); k += 2) {
      const V& p = points[k];
      const Brute brute = brute_closest(body.mesh(), p);
      const SurfacePoint plain = body.closest(p);
      for (const int hint : {-1, triangles, any_triangle(rng), brute.triangle}) {
        const SurfacePoint s = body.closest(p, hint);
        EXPECT_NEAR(s.distance, brute.distance, tol) << "p " << p.transpose() << " hint " << hint;
        EXPECT_NEAR(s.signed_distance, plain.signed_distance, tol) << "p " << p.transpose() << " hint " << hint;
        EXPECT_LE((s.point - plain.point).norm(), tol) << "p " << p.transpose() << " hint " << hint;
      }
    }
  }

  static RealMesh* featuretype_;
  static RealMesh* torso_;
};

RealMesh* RigidBodyRealMeshes::featuretype_ = nullptr;
RealMesh* RigidBodyRealMeshes::torso_ = nullptr;

TEST_F(RigidBodyRealMeshes, Loaded) {
  EXPECT_EQ(featuretype_->body->mesh().triangles.size(), 3476u);
  EXPECT_EQ(torso_->body->mesh().triangles.size(), 9365u);
  // Placed in metres: the 5-inch block is 0.127 m long.
  const BoundingBox box = featuretype_->body->box();
  EXPECT_NEAR(box.max.x() - box.min.x(), 0.127, 1e-7);
  EXPECT_EQ(featuretype_->body->name(), "featuretype");
}

TEST_F(RigidBodyRealMeshes, FeaturetypeClosestMatchesBruteForce) {
  check_closest_against_brute_force(*featuretype_->body, 101u);
}

TEST_F(RigidBodyRealMeshes, TorsoClosestMatchesBruteForce) {
  check_closest_against_brute_force(*torso_->body, 202u);
}

TEST_F(RigidBodyRealMeshes, FeaturetypeClosestWithinMatchesBruteForce) {
  check_closest_within_against_brute_force(*featuretype_->body, 111u);
}

TEST_F(RigidBodyRealMeshes, TorsoClosestWithinMatchesBruteForce) {
  check_closest_within_against_brute_force(*torso_->body, 222u);
}

TEST_F(RigidBodyRealMeshes, FeaturetypeHintedClosestMatchesBruteForce) {
  check_hinted_closest_against_brute_force(*featuretype_->body, 121u);
}

TEST_F(RigidBodyRealMeshes, TorsoHintedClosestMatchesBruteForce) {
  check_hinted_closest_against_brute_force(*torso_->body, 242u);
}

// A body moved along a tool path (turned and shifted) answers as its moved mesh: closest points
// against brute force over posed_mesh(), the normal turned with it, the inside still inside,
// and entries along a segment where the moved mesh has them.
TEST_F(RigidBodyRealMeshes, AMovedBodyAnswersAsItsMovedMesh) {
  RigidBody& body = *featuretype_->body;
  const TriangleMesh placed = body.mesh();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation_from_degrees(V(10.0, -25.0, 40.0));
  pose.translation() = V(0.03, -0.01, 0.05);
  body.move_to(pose);
  const TriangleMesh posed = body.posed_mesh();
  const double tol = 1e-9 + 1e-6 * body.box().diagonal();
  std::mt19937 rng(404u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const V& in_place : query_points(body, 404u)) {
    const V p = pose * in_place;
    const SurfacePoint s = body.closest(p);
    EXPECT_NEAR(s.distance, brute_closest(posed, p).distance, tol) << p.transpose();
    EXPECT_NEAR((p - s.point).norm(), s.distance, 1e-12 * (1.0 + s.distance));
    // The same answer as the unmoved body's for the unmoved point, carried along.
    body.move_to(Eigen::Isometry3d::Identity());
    const SurfacePoint at_home = body.closest(in_place);
    body.move_to(pose);
    if (at_home.distance <= tol) continue;  // on the surface, rounding decides the side and the crossing
    // Carried along, to the rounding of the transforms (the far points are 1000 diagonals out;
    // the CAD part's sliver triangles amplify a rounding of 1e-17 m in the query to ~1e-12 m),
    // where the same triangle answers (two at one distance may swap, as above).
    if (at_home.triangle == s.triangle) {
      EXPECT_LE((pose * at_home.point - s.point).norm(), 1e-10 * (body.box().diagonal() + s.distance));
      EXPECT_LE((pose.linear() * at_home.normal - s.normal).norm(), 1e-12);
    }
    EXPECT_EQ(at_home.signed_distance < 0.0, s.signed_distance < 0.0);
    const V to = p + 0.05 * body.box().diagonal() * V(unit(rng), unit(rng), unit(rng));
    const bool crosses = body.segment_crosses(p, to);
    body.move_to(Eigen::Isometry3d::Identity());
    const bool crosses_at_home = body.segment_crosses(in_place, pose.inverse() * to);
    body.move_to(pose);
    EXPECT_EQ(crosses, crosses_at_home) << p.transpose();
  }
  body.move_to(Eigen::Isometry3d::Identity());
  EXPECT_EQ(body.posed_mesh().vertices, placed.vertices);
}

TEST_F(RigidBodyRealMeshes, FeaturetypeIsOutwardAndOutsidePointsArePositive) {
  const RigidBody& body = *featuretype_->body;
  // SOURCES.md: oriented outward (positive enclosed volume), though not watertight.
  EXPECT_GT(signed_volume(body.mesh()), 0.0);
  // Points clearly outside the bounding box (by at least 1% of the diagonal) are outside
  // the body: their signed distance must be positive.
  std::mt19937 rng(303u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const BoundingBox box = body.box();
  const double diag = box.diagonal();
  for (int k = 0; k < 2000; ++k) {
    V p = box.min - V::Constant(0.3 * diag) + (box.max - box.min + V::Constant(0.6 * diag)).cwiseProduct(V(unit(rng), unit(rng), unit(rng)));
    const V outside_by = (box.min - p).cwiseMax(p - box.max);
    if (outside_by.maxCoeff() < 0.01 * diag) continue;
    const SurfacePoint s = body.closest(p);
    EXPECT_GT(s.signed_distance, 0.0) << p.transpose();
  }
}

// The torso is open at the neck: a point above the opening is outside, not "inside" because it
// lies below the plane of the rim's faces.
TEST_F(RigidBodyRealMeshes, TorsoAboveItsOpenNeckIsOutside) {
  const RigidBody& torso = *torso_->body;
  // (Just above the opening's middle the neck's inner wall is nearest: inside the tube.)
  for (const double above : {0.03, 0.3}) {
    const V p(0.0, torso.box().max.y() + above, 0.0);
    EXPECT_GT(torso.closest(p).signed_distance, 0.0) << above;
  }
}

TEST_F(RigidBodyRealMeshes, FeaturetypeFirstEntryMatchesBruteForce) {
  // Segments from outside the bounding box to random points inside it. Brute force: every
  // crossing in double; the first one, if it enters through the front of a face and is not
  // within a 1e-6 barycentric margin of an edge (Embree decides those in float; and this mesh
  // has cracks at T-junctions), is where first_entry must report the entry, to the float
  // precision of the ray plus the double refinement: 1e-6 × the diagonal.
  const RigidBody& body = *featuretype_->body;
  const TriangleMesh& mesh = body.mesh();
  const BoundingBox box = body.box();
  const double diag = box.diagonal();
  std::mt19937 rng(404u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, misses = 0;
  for (int k = 0; k < 1500; ++k) {
    const V direction = V(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
    const V centre = 0.5 * (box.min + box.max);
    const V from = centre + (0.6 + unit(rng)) * diag * direction;
    const V to = box.min + (box.max - box.min).cwiseProduct(V(unit(rng), unit(rng), unit(rng)));
    const std::vector<Crossing> hits = brute_crossings(mesh, from, to);
    const auto entry = body.first_entry(from, to);
    if (entry) {
      EXPECT_LE(entry->distance, 1e-6 * diag);  // on the surface
      EXPECT_LE(distance_to_segment(entry->point, from, to), 1e-6 * diag);  // on the segment
      EXPECT_TRUE(body.segment_crosses(from, to));
    }
    if (hits.empty()) {
      ++misses;
      EXPECT_FALSE(entry.has_value()) << "entry where brute force finds no crossing";
      continue;
    }
    const Crossing& first = hits.front();
    if (!first.front || first.margin < 1e-6) continue;
    ++compared;
    ASSERT_TRUE(entry.has_value()) << "from " << from.transpose() << " to " << to.transpose();
    EXPECT_LE((entry->point - (from + first.t * (to - from))).norm(), 1e-6 * diag);
    EXPECT_TRUE(body.segment_crosses(from, to));
  }
  EXPECT_GT(compared, 300);
  EXPECT_GT(misses, 10);
}

// ---------------------------------------------------------------------------------------------
// Hand-made boxes: exact answers.

class RigidBodyBox : public ::testing::Test {
 protected:
  RigidBodyBox() {
    TriangleMesh mesh;
    append_box(&mesh, V::Zero(), half_);
    body_ = std::make_unique<RigidBody>("box", mesh);
  }
  const V half_{1.0, 0.5, 0.25};
  std::unique_ptr<RigidBody> body_;
};

TEST_F(RigidBodyBox, IsClosedAndOutward) {
  EXPECT_NEAR(signed_volume(body_->mesh()), 8.0 * half_.prod(), 1e-15);
  EXPECT_EQ(body_->face_normal(0), V(-1, 0, 0));
}

TEST_F(RigidBodyBox, SignedDistanceIsExact) {
  // Random points in and around the box, plus points near its edges and corners, where the
  // sign comes from the edge and vertex pseudo-normals. Tolerance: coordinates of order 1,
  // a few roundings.
  std::mt19937 rng(505u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<V> points;
  for (int k = 0; k < 3000; ++k) points.push_back(2.0 * V(unit(rng), unit(rng), unit(rng)));
  for (int k = 0; k < 1000; ++k) points.push_back(half_.cwiseProduct(V(unit(rng), unit(rng), unit(rng))));
  for (int k = 0; k < 2000; ++k) {
    // Near a random corner, within 0.1 of it in every direction.
    const V corner(unit(rng) < 0 ? -half_.x() : half_.x(), unit(rng) < 0 ? -half_.y() : half_.y(),
                   unit(rng) < 0 ? -half_.z() : half_.z());
    V p = corner + 0.1 * V(unit(rng), unit(rng), unit(rng));
    if (k % 3 == 0) p.x() = 0.7 * unit(rng);  // near an edge along x instead
    points.push_back(p);
  }
  int inside = 0, outside = 0;
  for (const V& p : points) {
    const double exact = box_signed_distance(p, half_);
    const SurfacePoint s = body_->closest(p);
    EXPECT_NEAR(s.signed_distance, exact, 1e-12) << p.transpose();
    EXPECT_NEAR(s.distance, std::abs(exact), 1e-12);
    if (exact < -1e-9) {
      ++inside;
      EXPECT_LT(s.signed_distance, 0.0) << p.transpose();
    }
    if (exact > 1e-9) {
      ++outside;
      EXPECT_GT(s.signed_distance, 0.0) << p.transpose();
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 500);
}

TEST_F(RigidBodyBox, RotatedBoxSignedDistance) {
  std::mt19937 rng(606u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  TriangleMesh local;
  append_box(&local, V::Zero(), half_);
  for (int trial = 0; trial < 5; ++trial) {
    Placement placement;
    placement.rotation_deg = 180.0 * V(unit(rng), unit(rng), unit(rng));
    placement.translation_m = V(unit(rng), unit(rng), unit(rng));
    const RigidBody body("rotated box", place(local, placement));
    // The same placement applied to the query points, built as a one-vertex mesh.
    for (int k = 0; k < 500; ++k) {
      TriangleMesh probe;
      probe.vertices = {1.8 * V(unit(rng), unit(rng), unit(rng))};
      const V p = place(probe, placement).vertices[0];
      // Rotation rounding moves the box and the point by ~1e-16: tolerance 1e-12.
      EXPECT_NEAR(body.closest(p).signed_distance, box_signed_distance(probe.vertices[0], half_), 1e-12);
    }
  }
}

TEST_F(RigidBodyBox, ClosestOnTheSurfaceAndNormals) {
  // A point above the top face: closest point straight below, outward normal +z.
  const SurfacePoint top = body_->closest(V(0.3, -0.1, 2.0));
  EXPECT_NEAR((top.point - V(0.3, -0.1, 0.25)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((top.normal - V(0, 0, 1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(top.signed_distance, 1.75, 1e-15);
  // A point on the surface: distance 0.
  EXPECT_NEAR(body_->closest(V(1.0, 0.2, 0.1)).distance, 0.0, 1e-15);
  // Beyond a corner: the vertex pseudo-normal points out of the corner.
  const SurfacePoint corner = body_->closest(V(2.0, 1.5, 1.25));
  EXPECT_NEAR((corner.point - half_).norm(), 0.0, 1e-15);
  EXPECT_GT(corner.normal.minCoeff(), 0.0);
  EXPECT_NEAR(corner.signed_distance, std::sqrt(3.0), 1e-15);
}

TEST_F(RigidBodyBox, FirstEntry) {
  const V from(-3.0, 0.1, 0.05);
  // From outside through the face x = −1: the entry point is on the surface and the segment.
  for (const V& to : {V(0.0, 0.1, 0.05), V(3.0, 0.1, 0.05), V(-1.0, 0.1, 0.05)}) {
    const auto entry = body_->first_entry(from, to);
    ASSERT_TRUE(entry.has_value()) << to.transpose();
    // The crossing is refined in double: exact to a few ulps.
    EXPECT_NEAR((entry->point - V(-1.0, 0.1, 0.05)).norm(), 0.0, 1e-14);
    EXPECT_NEAR(entry->distance, 0.0, 1e-14);
    EXPECT_LE(distance_to_segment(entry->point, from, to), 1e-14);
    EXPECT_NEAR((entry->normal - V(-1, 0, 0)).norm(), 0.0, 1e-15);
    EXPECT_TRUE(body_->segment_crosses(from, to));
  }
  // Oblique, through the top face.
  const auto oblique = body_->first_entry(V(0.2, 0.1, 1.25), V(0.4, 0.1, -0.75));
  ASSERT_TRUE(oblique.has_value());
  EXPECT_NEAR((oblique->point - V(0.3, 0.1, 0.25)).norm(), 0.0, 1e-14);
  // Stops short of the box.
  EXPECT_FALSE(body_->first_entry(from, V(-1.5, 0.1, 0.05)).has_value());
  EXPECT_FALSE(body_->segment_crosses(from, V(-1.5, 0.1, 0.05)));
  // Leaving from inside: a crossing, but not an entry.
  EXPECT_FALSE(body_->first_entry(V(0, 0, 0), V(3, 0.2, 0.1)).has_value());
  EXPECT_TRUE(body_->segment_crosses(V(0, 0, 0), V(3, 0.2, 0.1)));
  // Missing the box.
  EXPECT_FALSE(body_->first_entry(V(-3, 2, 0), V(3, 2, 0)).has_value());
  EXPECT_FALSE(body_->segment_crosses(V(-3, 2, 0), V(3, 2, 0)));
  // Entirely inside.
  EXPECT_FALSE(body_->first_entry(V(0, 0, 0), V(0.5, 0.1, 0)).has_value());
  EXPECT_FALSE(body_->segment_crosses(V(0, 0, 0), V(0.5, 0.1, 0)));
  // No movement.
  EXPECT_FALSE(body_->first_entry(from, from).has_value());
  EXPECT_FALSE(body_->segment_crosses(from, from));
}

TEST_F(RigidBodyBox, RandomEntriesAreTheFirstCrossing) {
  // Segments from outside to inside always enter; the entry is where the slab method puts the
  // first crossing. Tolerance: the crossing is computed in double from the hit's plane.
  std::mt19937 rng(707u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int entries = 0;
  for (int k = 0; k < 2000; ++k) {
    const V from = 3.0 * V(unit(rng), unit(rng), unit(rng));
    const V to = 0.99 * half_.cwiseProduct(V(unit(rng), unit(rng), unit(rng)));
    if (box_signed_distance(from, half_) < 1e-3) continue;
    // Slab method: the segment enters at the largest of the per-axis entry parameters.
    const V d = to - from;
    double t_enter = 0.0;
    for (int axis = 0; axis < 3; ++axis)
      if (d[axis] != 0.0)
        t_enter = std::max(t_enter, std::min((-half_[axis] - from[axis]) / d[axis], (half_[axis] - from[axis]) / d[axis]));
    const auto entry = body_->first_entry(from, to);
    ASSERT_TRUE(entry.has_value()) << from.transpose() << " -> " << to.transpose();
    ++entries;
    EXPECT_LE((entry->point - (from + t_enter * d)).norm(), 1e-12) << from.transpose() << " -> " << to.transpose();
    EXPECT_LE(std::abs(box_signed_distance(entry->point, half_)), 1e-12);
    // And the reverse move (inside to outside) is never an entry.
    EXPECT_FALSE(body_->first_entry(to, from).has_value());
  }
  EXPECT_GT(entries, 1000);
}

// A solver's node that broke (NaN, Inf, or beyond float range, where Embree's boxes live) must
// get an answer, not an Embree assertion: no entry, no crossing, a non-finite or far distance.
TEST_F(RigidBodyBox, BrokenQueryPointsGetAnswersNotCrashes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const V inside(0.0, 0.1, 0.05);
  for (const V& broken : {V(nan, 0.0, 0.0), V(0.0, inf, 0.0), V(0.0, 0.0, -1e39)}) {
    EXPECT_FALSE(body_->first_entry(broken, inside).has_value()) << broken.transpose();
    EXPECT_FALSE(body_->first_entry(V(-3.0, 0.1, 0.05), broken).has_value()) << broken.transpose();
    EXPECT_FALSE(body_->segment_crosses(broken, inside)) << broken.transpose();
    EXPECT_FALSE(body_->closest_within(broken, 1.0).has_value()) << broken.transpose();
    const double d = body_->closest(broken).distance;
    EXPECT_TRUE(std::isnan(d) || d > 1e30) << broken.transpose() << ": " << d;
  }
}

TEST(RigidBody, FirstEntrySkipsExitFromAnotherBox) {
  // Two boxes in one mesh: starting inside the first, the move leaves it (a back-face
  // crossing, skipped) and then enters the second at x = 4.
  TriangleMesh mesh;
  append_box(&mesh, V(0, 0, 0), V(1, 1, 1));
  append_box(&mesh, V(5, 0, 0), V(1, 1, 1));
  const RigidBody body("two boxes", mesh);
  const auto entry = body.first_entry(V(0, 0.2, 0.3), V(10, 0.2, 0.3));
  ASSERT_TRUE(entry.has_value());
  EXPECT_NEAR((entry->point - V(4, 0.2, 0.3)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((entry->normal - V(-1, 0, 0)).norm(), 0.0, 1e-15);
  // Closest: a point between the boxes is 1.5 from both; one at x = 3 is nearer the second.
  EXPECT_NEAR(body.closest(V(3.0, 0, 0)).distance, 1.0, 1e-15);
  EXPECT_NEAR(body.closest(V(3.0, 0, 0)).point.x(), 4.0, 1e-15);
}

TEST(RigidBody, MovedBodyStillAnswers) {
  TriangleMesh mesh;
  append_box(&mesh, V::Zero(), V(1, 1, 1));
  RigidBody first("box", mesh);
  RigidBody second = std::move(first);
  EXPECT_NEAR(second.closest(V(0, 0, 3)).distance, 2.0, 1e-15);
  EXPECT_EQ(second.name(), "box");
}

// An open square plate (z = 0, normal +z): below its middle is inside, beyond its rim outside
// on either side, above it outside.
TEST(RigidBody, OpenPlateIsOutsideBeyondItsRim) {
  TriangleMesh plate;
  plate.vertices = {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)};
  plate.triangles = {{0, 1, 2}, {0, 2, 3}};
  const RigidBody body("plate", plate);
  EXPECT_LT(body.closest(V(0.5, 0.5, -0.1)).signed_distance, 0.0);
  EXPECT_GT(body.closest(V(0.5, 0.5, 0.1)).signed_distance, 0.0);
  for (const V& beyond : {V(1.5, 0.5, -0.1), V(-0.5, 0.5, -0.3), V(2.0, 2.0, -1.0), V(0.5, 1.2, -0.05)})
    EXPECT_DOUBLE_EQ(body.closest(beyond).signed_distance, body.closest(beyond).distance)
        << beyond.transpose();
}

// Watertight: every edge joins two faces that run it opposite ways. A cube and a UV sphere are;
// the open torso, a plate, a cube with a face missing, one turned over, or a third face on an
// edge are not.
TEST(RigidBody, WatertightOnlyWhenClosedAndConsistentlyOriented) {
  EXPECT_TRUE(RigidBody("cube", test::cube()).watertight());
  EXPECT_TRUE(RigidBody("sphere", test::uv_sphere(V::Zero(), 1.0, 12, 24)).watertight());
  TriangleMesh torn = test::cube();
  torn.triangles.pop_back();
  EXPECT_FALSE(RigidBody("torn", torn).watertight());
  TriangleMesh turned = test::cube();
  test::flip(&turned.triangles[3]);
  EXPECT_FALSE(RigidBody("turned", turned).watertight());
  TriangleMesh finned = test::cube();
  finned.vertices.push_back(V(0.5, -1.0, 0.0));
  finned.triangles.push_back({0, 1, 8});  // a fin on the edge 0–1, which two faces already join
  EXPECT_FALSE(RigidBody("finned", finned).watertight());
  TriangleMesh plate;
  plate.vertices = {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)};
  plate.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_FALSE(RigidBody("plate", plate).watertight());
  const TriangleMesh torso = read_mesh(test::source_path("molds/garmentcode_mean_female_torso_open.obj"));
  EXPECT_FALSE(RigidBody("torso_open", torso).watertight());
}

TEST(RigidBody, InvalidMeshesThrow) {
  TriangleMesh empty;
  EXPECT_THROW(RigidBody("empty", empty), std::invalid_argument);
  TriangleMesh no_triangles;
  no_triangles.vertices = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
  EXPECT_THROW(RigidBody("no triangles", no_triangles), std::invalid_argument);
  for (const std::array<int, 3>& bad : {std::array<int, 3>{0, 1, 3}, std::array<int, 3>{-1, 1, 2},
                                        std::array<int, 3>{0, 1000000, 2}}) {
    TriangleMesh mesh = no_triangles;
    mesh.triangles = {{0, 1, 2}, bad};
    EXPECT_THROW(RigidBody("bad index", mesh), std::invalid_argument);
  }
  TriangleMesh non_finite = no_triangles;
  non_finite.triangles = {{0, 1, 2}};
  non_finite.vertices[1].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(RigidBody("nan", non_finite), std::invalid_argument);
  non_finite.vertices[1].y() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(RigidBody("inf", non_finite), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::rigid_body_test
