// RigidBody::valley_normals: the two faces of a valley a point lies in, against a box and a
// groove known by hand and against a brute-force scan of every triangle of a real CAD part
// (featuretype) at its vertices, on its edges and inside its faces.
#include "fabform/geometry/rigid_body.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "fabform/angles.hpp"
#include "fabform/geometry/closest_point.hpp"
#include "fabform/geometry/placement.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "support/shapes.hpp"
#include "test_paths.hpp"

namespace fabform::rigid_body_valley_test {
namespace {

using V = Eigen::Vector3d;

// Whether {a, b} is {p, q} in either order, to rounding.
bool same_pair(const std::array<V, 2>& got, const V& p, const V& q) {
  const double tol = 1e-12;
  return ((got[0] - p).norm() < tol && (got[1] - q).norm() < tol) ||
         ((got[0] - q).norm() < tol && (got[1] - p).norm() < tol);
}

// The inside of a box (the cube turned inside out): its edges are valleys.
TriangleMesh inside_of_a_box() {
  TriangleMesh mesh = test::cube();
  for (auto& triangle : mesh.triangles) test::flip(&triangle);
  return mesh;
}

TEST(RigidBodyValley, AnEdgeInsideABoxIsAValleyOfItsTwoFaces) {
  const RigidBody body("box", inside_of_a_box());
  const auto top_front = body.valley_normals({0.5, 0.0, 1.0});
  ASSERT_TRUE(top_front);
  EXPECT_TRUE(same_pair(*top_front, V::UnitY(), -V::UnitZ()));
  // Within kCreaseShare of the size of the edge, still in it; beyond, on the top face alone.
  const double reach = kCreaseShare * std::sqrt(3.0);
  EXPECT_TRUE(body.valley_normals({0.5, 0.5 * reach, 1.0}));
  EXPECT_FALSE(body.valley_normals({0.5, 2.0 * reach, 1.0}));
  // Inside a face, or on the diagonal that splits it into two triangles of one plane: none.
  EXPECT_FALSE(body.valley_normals({0.3, 0.6, 1.0}));
  EXPECT_FALSE(body.valley_normals({0.5, 0.5, 1.0}));
}

TEST(RigidBodyValley, AnOutsideEdgeIsARidgeNotAValley) {
  const RigidBody body("cube", test::cube());
  EXPECT_FALSE(body.valley_normals({0.5, 0.0, 1.0}));
  EXPECT_FALSE(body.valley_normals({1.0, 1.0, 1.0}));
}

TEST(RigidBodyValley, AnInsideCornerGivesTwoOfItsThreeFaces) {
  const RigidBody body("box", inside_of_a_box());
  const auto corner = body.valley_normals({1.0, 1.0, 1.0});
  ASSERT_TRUE(corner);
  for (const V& n : *corner) EXPECT_NEAR(std::min({n.x(), n.y(), n.z()}), -1.0, 1e-15);
  EXPECT_NEAR((*corner)[0].dot((*corner)[1]), 0.0, 1e-15);
}

TEST(RigidBodyValley, AMovedBodysNormalsTurnWithIt) {
  RigidBody body("box", inside_of_a_box());
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.rotate(Eigen::AngleAxisd(0.5 * kPi, V::UnitZ()));
  pose.pretranslate(V(2.0, 0.0, 0.0));
  body.move_to(pose);
  // The top front edge (y = 0, z = 1) turned a quarter about z and shifted: x = 2, z = 1.
  const auto edge = body.valley_normals(pose * V(0.5, 0.0, 1.0));
  ASSERT_TRUE(edge);
  EXPECT_TRUE(same_pair(*edge, -V::UnitX(), -V::UnitZ()));
}

// A groove whose faces rise by `degrees` on either side: a valley when they turn by more than
// kCreaseAngleDeg between them.
TEST(RigidBodyValley, FacesThatBarelyTurnAreOnePlane) {
  for (const double degrees : {0.25, 2.0}) {
    const double s = std::tan(degrees * kPi / 180.0);
    TriangleMesh groove;
    groove.vertices = {{-1, 0, s}, {0, 0, 0}, {0, 1, 0}, {-1, 1, s}, {1, 0, s}, {1, 1, s}};
    groove.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
    const RigidBody body("groove", groove);
    EXPECT_EQ(body.valley_normals({0.0, 0.5, 0.0}).has_value(), 2.0 * degrees > kCreaseAngleDeg) << degrees;
  }
}

// The widest pair of faces within the reach of points on featuretype's surface, by brute force.
TEST(RigidBodyValley, FeaturetypeMatchesBruteForce) {
  Placement inches;
  inches.metres_per_unit = 0.0254;
  const RigidBody body("featuretype", place(read_mesh(test::source_path("molds/trimesh_featuretype.STL")), inches));
  const TriangleMesh& mesh = body.mesh();
  const double reach = kCreaseShare * body.box().diagonal();
  const double widest_allowed = std::cos(kCreaseAngleDeg * kPi / 180.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int valleys = 0, checked = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 7) {
    const auto& tri = mesh.triangles[t];
    const V& a = mesh.vertices[static_cast<std::size_t>(tri[0])];
    const V& b = mesh.vertices[static_cast<std::size_t>(tri[1])];
    const V& c = mesh.vertices[static_cast<std::size_t>(tri[2])];
    const double u = unit(rng), w = unit(rng) * (1.0 - u);
    for (const V& p : {a, V(0.5 * (a + b)), V(a + u * (b - a) + w * (c - a))}) {
      std::vector<int> near;
      for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto& q = mesh.triangles[k];
        const V on = closest_point_on_triangle(p, mesh.vertices[static_cast<std::size_t>(q[0])],
                                               mesh.vertices[static_cast<std::size_t>(q[1])],
                                               mesh.vertices[static_cast<std::size_t>(q[2])])
                         .point;
        if ((p - on).norm() <= reach && !body.face_normal(static_cast<int>(k)).isZero()) near.push_back(static_cast<int>(k));
      }
      const auto centre = [&](int k) {
        const auto& q = mesh.triangles[static_cast<std::size_t>(k)];
        return V((mesh.vertices[static_cast<std::size_t>(q[0])] + mesh.vertices[static_cast<std::size_t>(q[1])] +
                  mesh.vertices[static_cast<std::size_t>(q[2])]) / 3.0);
      };
      double smallest = widest_allowed;
      for (std::size_t i = 0; i < near.size(); ++i)
        for (std::size_t j = i + 1; j < near.size(); ++j) {
          const V& ni = body.face_normal(near[i]);
          const V& nj = body.face_normal(near[j]);
          if (ni.dot(centre(near[j]) - p) > 0.0 && nj.dot(centre(near[i]) - p) > 0.0) smallest = std::min(smallest, ni.dot(nj));
        }
      const auto got = body.valley_normals(p);
      ASSERT_EQ(got.has_value(), smallest < widest_allowed) << "p " << p.transpose();
      if (got) {
        EXPECT_NEAR((*got)[0].dot((*got)[1]), smallest, 1e-12);
        ++valleys;
      }
      ++checked;
    }
  }
  EXPECT_GT(valleys, checked / 20);  // the part's pockets meet their floors in valleys
}

}  // namespace
}  // namespace fabform::rigid_body_valley_test
