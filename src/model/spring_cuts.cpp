#include "fabform/model/spring_cuts.hpp"

#include <algorithm>
#include <cmath>

#include "fabform/geometry/nearby_queries.hpp"
#include "fabform/model/spring_path.hpp"

namespace fabform {
namespace {

constexpr int kSamples = 32;
constexpr double kCutShare = 0.01;      // of the spring's rest length (spring_cuts.hpp)
constexpr double kRefinedShare = 1e-7;  // of the segment: where the search for the deepest point stops
const double kGoldenShare = (std::sqrt(5.0) - 1.0) / 2.0;

// How deep the point at t ∈ [0, 1] of the segment a–b lies inside body `body` (negative outside).
// Successive points are near each other, which the queries make cheap.
double depth_at(NearbyQueries& queries, int body, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t) {
  return -queries.closest(body, a + t * (b - a)).signed_distance;
}

// How far inside the body the segment reaches: the deepest of its sample points, then refined
// between that sample's neighbours by a golden-section search (the depth rises to a corner and
// falls past it), to kRefinedShare of the segment, unless the bracket is proved no deeper than
// `enough` first: its points lie within its width of a point measured, and depth changes no
// faster than the point moves. Most segments that cross a surface are chords resting on it,
// settled so in a few steps.
double depth_inside(NearbyQueries& queries, int body, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    double enough) {
  const auto depth = [&](double t) { return depth_at(queries, body, a, b, t); };
  int best = 1;
  double deepest = depth(1.0 / kSamples);
  for (int k = 2; k < kSamples; ++k)
    if (const double d = depth(static_cast<double>(k) / kSamples); d > deepest) deepest = d, best = k;
  const double length = (b - a).norm();
  double lo = static_cast<double>(best - 1) / kSamples, hi = static_cast<double>(best + 1) / kSamples;
  double left = hi - kGoldenShare * (hi - lo), right = lo + kGoldenShare * (hi - lo);
  double at_left = depth(left), at_right = depth(right);
  while (hi - lo > kRefinedShare && std::max(at_left, at_right) + (hi - lo) * length > enough) {
    if (at_left < at_right) {
      lo = left, left = right, at_left = at_right;
      right = lo + kGoldenShare * (hi - lo), at_right = depth(right);
    } else {
      hi = right, right = left, at_right = at_left;
      left = hi - kGoldenShare * (hi - lo), at_left = depth(left);
    }
  }
  return std::max({deepest, at_left, at_right, 0.0});
}

// How deep the straight segment a–b reaches into some body (0 when it stays out), exactly where
// that is deeper than `enough`.
double deepest_into(const Model& model, NearbyQueries& queries, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    double enough) {
  double deepest = 0.0;
  for (std::size_t body = 0; body < model.bodies.size(); ++body)
    if (model.bodies[body].segment_crosses(a, b))
      deepest = std::max(deepest, depth_inside(queries, static_cast<int>(body), a, b, enough));
  return deepest;
}

struct SpringDepth {
  bool wrapped = false;  // over a body's edge, in two legs
  double depth_m = 0.0;  // how deep it (or a leg) reaches into a body; exact beyond a cut's depth
};

SpringDepth spring_depth(const Model& model, NearbyQueries& queries, const Spring& spring,
                         const std::vector<Eigen::Vector3d>& x) {
  if (spring.kind == SpringKind::bend) return {};  // spans two cells: its segment is no fabric
  const Eigen::Vector3d& a = x[static_cast<std::size_t>(spring.a)];
  const Eigen::Vector3d& b = x[static_cast<std::size_t>(spring.b)];
  if (!a.allFinite() || !b.allFinite()) return {};
  // A spring wrapped over an edge runs in two legs, each of which may cut another feature.
  const double enough = kCutShare * spring.rest_length;  // not a cut (find_spring_cuts)
  const auto wrap = spring_wrap(model, spring, a, b);
  if (!wrap) return {false, deepest_into(model, queries, a, b, enough)};
  return {true, std::max(deepest_into(model, queries, a, wrap->point, enough),
                         deepest_into(model, queries, wrap->point, b, enough))};
}

}  // namespace

SpringCuts find_spring_cuts(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const std::vector<Spring>& springs = model.fabric.springs();
  // Each spring measured on its own (in parallel), then counted in order.
  std::vector<SpringDepth> measured(springs.size());
  for_each_nearby(static_cast<int>(springs.size()), model.bodies, [&](int s, NearbyQueries& queries) {
    measured[static_cast<std::size_t>(s)] = spring_depth(model, queries, springs[static_cast<std::size_t>(s)], x);
  });
  SpringCuts cuts;
  for (std::size_t s = 0; s < springs.size(); ++s) {
    cuts.over_edges += measured[s].wrapped ? 1 : 0;
    const double depth = measured[s].depth_m;
    if (depth <= kCutShare * springs[s].rest_length) continue;  // a chord of a curve, or grazing
    ++cuts.springs;
    if (depth > cuts.deepest_m) cuts.deepest_m = depth, cuts.deepest_spring = static_cast<int>(s);
  }
  return cuts;
}

}  // namespace fabform
