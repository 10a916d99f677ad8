// NearbyQueries and for_each_nearby (nearby_queries.hpp) against RigidBody::closest point by
// point: a fabric-like sheet of points over a sphere and a cube, each query started from the
// previous point's answer, must find what the unhinted query finds, with one thread or two.
#include "fabform/geometry/nearby_queries.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <vector>

#include "fabform/thread_count.hpp"
#include "support/shapes.hpp"
#include "support/threads_restored.hpp"

namespace fabform::nearby_queries_test {
namespace {

using V = Eigen::Vector3d;

std::vector<RigidBody> sphere_and_cube() {
  std::vector<RigidBody> bodies;
  bodies.emplace_back("sphere", test::uv_sphere(V(0.0, 0.0, 0.0), 0.03, 64, 128));
  bodies.emplace_back("cube", test::cube(V(0.02, -0.05, 0.01), 0.02));
  return bodies;
}

// A 121 × 121 sheet over 12 × 12 cm, in index order like a fabric's nodes: a bump whose
// centre dips into the sphere and whose corner runs through the cube, so the points lie
// outside, on and inside the bodies, near and far (14 641 points: enough for two threads).
std::vector<V> sheet() {
  std::vector<V> points;
  const int n = 121;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -0.06 + 0.12 * i / (n - 1), y = -0.06 + 0.12 * j / (n - 1);
      points.emplace_back(x, y, 0.028 + 0.01 * std::cos(40.0 * x) * std::sin(30.0 * y));
    }
  return points;
}

void expect_same_answer(const SurfacePoint& got, const SurfacePoint& want, const V& p) {
  // Triangles at the same distance may be named either way: the point, distance and side agree.
  const double tol = 1e-12;
  EXPECT_NEAR(got.distance, want.distance, tol) << p.transpose();
  EXPECT_NEAR(got.signed_distance, want.signed_distance, tol) << p.transpose();
  EXPECT_LE((got.point - want.point).norm(), tol) << p.transpose();
  EXPECT_LE((got.normal - want.normal).norm(), 1e-9) << p.transpose();
}

TEST(NearbyQueries, AnswerAsTheUnhintedQueryForEachBodyInTurn) {
  const std::vector<RigidBody> bodies = sphere_and_cube();
  const std::vector<V> points = sheet();
  NearbyQueries queries(bodies);
  int inside[2] = {0, 0};
  for (std::size_t k = 0; k < points.size(); k += 3)
    for (int b = 0; b < 2; ++b) {
      const SurfacePoint s = queries.closest(b, points[k]);
      expect_same_answer(s, bodies[static_cast<std::size_t>(b)].closest(points[k]), points[k]);
      inside[b] += s.signed_distance < 0.0;
    }
  EXPECT_GT(inside[0], 100);  // the sheet does reach into each body
  EXPECT_GT(inside[1], 10);
}

TEST(NearbyQueries, APointThatIsNotFiniteIsAnsweredAsClosestDoes) {
  const std::vector<RigidBody> bodies = sphere_and_cube();
  NearbyQueries queries(bodies);
  queries.closest(0, V(0.0, 0.0, 0.05));
  const V broken(std::nan(""), 0.0, 0.0);
  const SurfacePoint s = queries.closest(0, broken);
  EXPECT_EQ(s.triangle, bodies[0].closest(broken).triangle);
}

// Whenever surely_outside says so, closest() agrees that the point is outside by more than the
// clearance; and along the sheet it says so for most points, which is what it is for.
TEST(NearbyQueries, SurelyOutsideNeverClaimsAPointThatIsNot) {
  const std::vector<RigidBody> bodies = sphere_and_cube();
  ASSERT_TRUE(bodies[0].watertight() && bodies[1].watertight());
  const std::vector<V> points = sheet();
  for (const double clearance : {0.0, 2e-3}) {
    NearbyQueries queries(bodies);
    int settled = 0;
    for (const V& p : points)
      for (int b = 0; b < 2; ++b) {
        if (!queries.surely_outside(b, p, clearance)) {
          queries.closest(b, p);
          continue;
        }
        ++settled;
        EXPECT_GT(bodies[static_cast<std::size_t>(b)].closest(p).signed_distance, clearance) << p.transpose();
      }
    EXPECT_GT(settled, static_cast<int>(points.size())) << clearance;  // over half the 2 × 14 641 asked
  }
}

// An open body has points behind its faces that no surface separates from points in front:
// there an earlier answer proves nothing, and none is claimed.
TEST(NearbyQueries, SurelyOutsideClaimsNothingOfABodyThatIsNotWatertight) {
  TriangleMesh open_cube = test::cube(V(-0.01, -0.01, -0.01), 0.02);
  open_cube.triangles.pop_back();
  std::vector<RigidBody> bodies;
  bodies.emplace_back("open cube", open_cube);
  ASSERT_FALSE(bodies[0].watertight());
  NearbyQueries queries(bodies);
  for (const V& p : sheet()) {
    EXPECT_FALSE(queries.surely_outside(0, p, 0.0));
    queries.closest(0, p);
  }
}

TEST(ForEachNearby, VisitsEveryPointOnceWithTheSameAnswersOnOneThreadOrTwo) {
  const std::vector<RigidBody> bodies = sphere_and_cube();
  const std::vector<V> points = sheet();
  const int count = static_cast<int>(points.size());
  ASSERT_GE(count, kMinParallelItems);
  const test::ThreadsRestored restored;
  for (const int threads : {1, 2}) {
    use_threads(threads);
    std::vector<std::atomic<int>> visits(points.size());
    std::vector<SurfacePoint> answers(points.size());
    for_each_nearby(count, bodies, [&](int k, NearbyQueries& queries) {
      const auto i = static_cast<std::size_t>(k);
      ++visits[i];
      answers[i] = queries.closest(1, points[i]);
    });
    for (std::size_t k = 0; k < points.size(); ++k) {
      ASSERT_EQ(visits[k].load(), 1) << k;
      if (k % 7 == 0) expect_same_answer(answers[k], bodies[1].closest(points[k]), points[k]);
    }
  }
}

}  // namespace
}  // namespace fabform::nearby_queries_test
