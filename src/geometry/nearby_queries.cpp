#include "fabform/geometry/nearby_queries.hpp"

#include <algorithm>
#include <limits>

#include "fabform/thread_count.hpp"

namespace fabform {
namespace {

// Long enough that a run's first, unbounded query is rare; short enough to share the work.
constexpr int kRunLength = 256;

}  // namespace

NearbyQueries::NearbyQueries(const std::vector<RigidBody>& bodies)
    : bodies_(&bodies), last_(bodies.size()) {}

SurfacePoint NearbyQueries::closest(int body, const Eigen::Vector3d& p) {
  Answer& last = last_[static_cast<std::size_t>(body)];
  const SurfacePoint s = (*bodies_)[static_cast<std::size_t>(body)].closest(p, last.triangle);
  last = {s.triangle, p, s.signed_distance};
  return s;
}

double NearbyQueries::clearance_bound(int body, const Eigen::Vector3d& p) const {
  const Answer& last = last_[static_cast<std::size_t>(body)];
  const double bound = last.signed_distance - (p - last.at).norm();
  const bool proves = last.triangle >= 0 && (*bodies_)[static_cast<std::size_t>(body)].watertight() && bound > 0.0;
  return proves ? bound : -std::numeric_limits<double>::infinity();
}

void for_each_nearby(int count, const std::vector<RigidBody>& bodies,
                     const std::function<void(int, NearbyQueries&)>& visit) {
  const int runs = (count + kRunLength - 1) / kRunLength;
#pragma omp parallel for schedule(dynamic, 1) if (count >= kMinParallelItems)
  for (int run = 0; run < runs; ++run) {
    NearbyQueries queries(bodies);
    for (int k = run * kRunLength; k < std::min(count, (run + 1) * kRunLength); ++k) visit(k, queries);
  }
}

}  // namespace fabform
