// RigidBody::convex_edges: a roof's ridge, whole or cracked (a T-junction: one face meets the
// ridge in one long edge, the other in two short ones, as CAD tessellations leave them), is
// found once along its length, and a valley is not found at all.
#include "fabform/geometry/rigid_body.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fabform/angles.hpp"

namespace fabform::rigid_body_edges_test {
namespace {

using V = Eigen::Vector3d;

// A roof over [−1, 1] × [0, 1] whose faces fall by 30° from its ridge on the y axis (z = ±h
// at x = ±1, `sign` −1 for a roof, +1 for a valley); the right face meets the ridge at
// (0, 0.4, 0) too when `cracked` (off the middle, where the long edge looks for its partner).
TriangleMesh roof(bool cracked, double sign = -1.0) {
  const double h = sign * std::tan(kPi / 6.0);
  TriangleMesh mesh;
  mesh.vertices = {{-1, 0, h}, {0, 0, 0}, {0, 1, 0}, {-1, 1, h}, {1, 0, h}, {1, 1, h}, {0, 0.4, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  if (cracked) mesh.triangles.insert(mesh.triangles.end(), {{1, 4, 6}, {6, 4, 5}, {6, 5, 2}});
  else mesh.triangles.insert(mesh.triangles.end(), {{1, 4, 5}, {1, 5, 2}});
  return mesh;  // counter-clockwise seen from above: every face looks up
}

// The length of the found edges that lie on the ridge (x = z = 0).
double ridge_length(const std::vector<SharpEdge>& edges) {
  double length = 0.0;
  for (const SharpEdge& e : edges)
    if (std::abs(e.from.x()) + std::abs(e.from.z()) + std::abs(e.to.x()) + std::abs(e.to.z()) < 1e-12)
      length += (e.to - e.from).norm();
  return length;
}

TEST(RigidBodyConvexEdges, ARidgeIsFoundOnceAlongItsLength) {
  for (const bool cracked : {false, true}) {
    const RigidBody body("roof", roof(cracked));
    const std::vector<SharpEdge> edges = body.convex_edges(10.0);
    EXPECT_NEAR(ridge_length(edges), 1.0, 1e-12) << (cracked ? "cracked" : "whole");
    for (const SharpEdge& e : edges) EXPECT_NEAR(e.normal_a.dot(e.normal_b), std::cos(kPi / 3.0), 1e-12);
  }
}

TEST(RigidBodyConvexEdges, TheRidgeTurnsLessThanAskedOrIsAValley) {
  EXPECT_EQ(ridge_length(RigidBody("roof", roof(true)).convex_edges(61.0)), 0.0);
  EXPECT_EQ(ridge_length(RigidBody("valley", roof(true, 1.0)).convex_edges(10.0)), 0.0);
}

}  // namespace
}  // namespace fabform::rigid_body_edges_test
