#include "fabform/model/spring_cuts.hpp"

#include <algorithm>

#include "fabform/model/spring_path.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {
namespace {

constexpr int kSamples = 32;
constexpr double kCutShare = 0.01;  // of the spring's rest length (spring_cuts.hpp)

// A point of a spring that reaches into a body lies within the spring's length of its surface
// (the spring's ends are outside): a search that near is cheap; farther, a full one.
double depth_at(const RigidBody& body, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t) {
  const Eigen::Vector3d p = a + t * (b - a);
  const auto near = body.closest_within(p, (b - a).norm());
  return -(near ? *near : body.closest(p)).signed_distance;
}

// How far inside the body the segment reaches: the deepest of its sample points, then refined
// between that sample's neighbours by a ternary search (the depth rises to a corner and falls
// past it), to a ten-millionth of the spring.
double depth_inside(const RigidBody& body, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  int best = 1;
  double depth = depth_at(body, a, b, 1.0 / kSamples);
  for (int k = 2; k < kSamples; ++k)
    if (const double d = depth_at(body, a, b, static_cast<double>(k) / kSamples); d > depth) depth = d, best = k;
  double lo = static_cast<double>(best - 1) / kSamples, hi = static_cast<double>(best + 1) / kSamples;
  for (int step = 0; step < 40; ++step) {
    const double left = lo + (hi - lo) / 3.0, right = hi - (hi - lo) / 3.0;
    if (depth_at(body, a, b, left) < depth_at(body, a, b, right)) lo = left;
    else hi = right;
  }
  return std::max({depth, depth_at(body, a, b, 0.5 * (lo + hi)), 0.0});
}

// How deep the straight segment a–b reaches into some body; 0 when it stays out.
double deepest_into(const Model& model, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  double deepest = 0.0;
  for (const RigidBody& body : model.bodies)
    if (body.segment_crosses(a, b)) deepest = std::max(deepest, depth_inside(body, a, b));
  return deepest;
}

struct SpringDepth {
  bool wrapped = false;  // over a body's edge, in two legs
  double depth_m = 0.0;  // how deep it (or a leg) reaches into a body
};

SpringDepth spring_depth(const Model& model, const Spring& spring, const std::vector<Eigen::Vector3d>& x) {
  if (spring.kind == SpringKind::bend) return {};  // spans two cells: its segment is no fabric
  const Eigen::Vector3d& a = x[static_cast<std::size_t>(spring.a)];
  const Eigen::Vector3d& b = x[static_cast<std::size_t>(spring.b)];
  if (!a.allFinite() || !b.allFinite()) return {};
  // A spring wrapped over an edge runs in two legs, each of which may cut another feature.
  const auto wrap = spring_wrap(model, spring, a, b);
  if (!wrap) return {false, deepest_into(model, a, b)};
  return {true, std::max(deepest_into(model, a, wrap->point), deepest_into(model, wrap->point, b))};
}

}  // namespace

SpringCuts find_spring_cuts(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const std::vector<Spring>& springs = model.fabric.springs();
  // Each spring measured on its own (in parallel), then counted in order.
  std::vector<SpringDepth> measured(springs.size());
#pragma omp parallel for schedule(dynamic, 64) if (springs.size() >= kMinParallelItems)
  for (int s = 0; s < static_cast<int>(springs.size()); ++s)
    measured[static_cast<std::size_t>(s)] = spring_depth(model, springs[static_cast<std::size_t>(s)], x);
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
