// A segment over one sharp edge (edge_wrap.hpp): the wrap point and length against a brute-force
// search along the edge (the shortest way a string takes over it), the legs kept out of the
// wedge, the length falling to the straight one as the segment rises to the edge, and the
// segments that must not wrap: above the edge, lying on a face, parallel to it, past its end.
#include "fabform/geometry/edge_wrap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fabform::edge_wrap_test {
namespace {

using V = Eigen::Vector3d;

// A box's edge along y from y = 0 to y = 1 at x = z = 0; the body is x < 0, z < 0 (top face
// +z, side face +x).
SharpEdge box_edge() { return {V(0.0, 0.0, 0.0), V(0.0, 1.0, 0.0), V::UnitZ(), V::UnitX()}; }

// min over p on the edge of |a − p| + |p − b|, by a scan of 10⁵ points refined by golden sections.
struct Brute {
  double length = std::numeric_limits<double>::infinity();
  V point = V::Zero();
};
Brute brute_wrap(const SharpEdge& edge, const V& a, const V& b) {
  const auto length_at = [&](double s) {
    const V p = edge.from + s * (edge.to - edge.from);
    return (a - p).norm() + (b - p).norm();
  };
  constexpr int kScan = 100000;
  int best = 0;
  for (int k = 1; k <= kScan; ++k)
    if (length_at(static_cast<double>(k) / kScan) < length_at(static_cast<double>(best) / kScan)) best = k;
  double lo = std::max(0.0, (best - 1.0) / kScan), hi = std::min(1.0, (best + 1.0) / kScan);
  for (int i = 0; i < 100; ++i) {
    const double l = lo + 0.382 * (hi - lo), r = hi - 0.382 * (hi - lo);
    if (length_at(l) < length_at(r)) hi = r;
    else lo = l;
  }
  const double s = 0.5 * (lo + hi);
  return {length_at(s), edge.from + s * (edge.to - edge.from)};
}

bool inside_wedge(const SharpEdge& edge, const V& x) {
  return (x - edge.from).dot(edge.normal_a) < -1e-12 && (x - edge.from).dot(edge.normal_b) < -1e-12;
}

TEST(EdgeWrap, TheWrapIsTheShortestWayOverTheEdge) {
  const SharpEdge edge = box_edge();
  // Above the top face to beside the side face, obliquely across the edge, at several slants.
  for (const double dy : {0.0, 0.2, 0.5, -0.15}) {
    const V a(-0.3, 0.4, 0.05), b(0.04, 0.4 + dy, -0.35);
    const auto wrap = wrap_over(edge, a, b, 0.0);
    ASSERT_TRUE(wrap) << dy;
    const Brute brute = brute_wrap(edge, a, b);
    EXPECT_NEAR(wrap->length, brute.length, 1e-12) << dy;
    EXPECT_NEAR((wrap->point - brute.point).norm(), 0.0, 1e-7) << dy;
    EXPECT_GT(wrap->length, (b - a).norm()) << dy;
    EXPECT_FALSE(wrap->at_end);
    EXPECT_NEAR(std::abs(wrap->axis.dot(V::UnitY())), 1.0, 1e-15);
    for (int k = 1; k < 100; ++k) {
      const double t = k / 100.0;
      EXPECT_FALSE(inside_wedge(edge, a + t * (wrap->point - a))) << dy << " leg a, t " << t;
      EXPECT_FALSE(inside_wedge(edge, wrap->point + t * (b - wrap->point))) << dy << " leg b, t " << t;
    }
  }
}

TEST(EdgeWrap, PastTheEdgesEndTheWrapHoldsAtTheEnd) {
  const SharpEdge edge = box_edge();
  // Under the edge near its end at y = 1 (closest to it at y ≈ 0.95), slanting so the unfolded
  // line crosses beyond the end (at y ≈ 1.08).
  const V a(-0.24, 0.61, 0.01), b(0.04, 1.95, -0.44);
  const auto wrap = wrap_over(edge, a, b, 0.0);
  ASSERT_TRUE(wrap);
  EXPECT_TRUE(wrap->at_end);
  EXPECT_NEAR((wrap->point - edge.to).norm(), 0.0, 1e-15);
  EXPECT_NEAR(wrap->length, brute_wrap(edge, a, b).length, 1e-12);
}

// Lowered by d under the edge, a symmetric segment of half-length h wraps to 2√(h² + d²):
// O(d²/h) longer, so the energy does not jump as a spring comes onto the edge.
TEST(EdgeWrap, AsTheSegmentRisesToTheEdgeTheWrapFallsToItsLength) {
  const SharpEdge edge = box_edge();
  const double h = 0.1;
  for (const double d : {1e-2, 1e-4, 1e-6, 1e-9}) {
    // The segment from above the top face to beside the side, centred under the edge at depth d
    // along the bisector.
    const V centre = -d * V(1.0, 0.0, 1.0).normalized();
    const V along = V(1.0, 0.0, -1.0).normalized();
    const V a = centre - h * along, b = centre + h * along;
    const auto wrap = wrap_over(edge, a, b, 0.0);
    ASSERT_TRUE(wrap) << d;
    EXPECT_NEAR(wrap->length, 2.0 * std::sqrt(h * h + d * d), 1e-14) << d;
  }
}

TEST(EdgeWrap, SegmentsThatDoNotPassUnderTheEdgeDoNotWrap) {
  const SharpEdge edge = box_edge();
  const V along = V(1.0, 0.0, -1.0).normalized();
  const V over = 0.01 * V(1.0, 0.0, 1.0).normalized();
  EXPECT_FALSE(wrap_over(edge, over - 0.1 * along, over + 0.1 * along, 0.0)) << "above the edge";
  EXPECT_FALSE(wrap_over(edge, V(-0.3, 0.5, 0.0), V(-0.05, 0.6, 0.0), 0.0)) << "lying on the top face";
  EXPECT_FALSE(wrap_over(edge, V(-0.3, 0.5, 0.0), V(0.0, 0.6, 0.0), 0.0)) << "ending on the edge";
  EXPECT_FALSE(wrap_over(edge, V(-0.1, 0.2, -0.1), V(-0.1, 0.8, -0.1), 0.0)) << "parallel, inside";
  EXPECT_FALSE(wrap_over(edge, V(-0.3, 1.5, 0.05), V(0.04, 1.5, -0.35), 0.0)) << "past the edge's end";
}

TEST(EdgeWrap, ADegenerateEdgeWrapsNothing) {
  const SharpEdge point{V::Zero(), V::Zero(), V::UnitZ(), V::UnitX()};
  EXPECT_FALSE(wrap_over(point, V(-0.3, 0.0, 0.05), V(0.04, 0.0, -0.35), 0.0));
}

}  // namespace
}  // namespace fabform::edge_wrap_test
