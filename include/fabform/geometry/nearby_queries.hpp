#pragma once
// Closest-point queries at points that lie near each other in turn, as a fabric's nodes do in
// index order: each body's query starts from the triangle it answered for the previous point,
// whose distance bounds the search. And where only the side matters, a point near one found
// well outside a watertight body is known to be outside without a query: a node far above a
// body, whose query visits a hundred triangles or more, is settled by one subtraction.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "fabform/geometry/rigid_body.hpp"

namespace fabform {

/// One run of queries (one thread's): the answers are closest()'s, point by point. The bodies
/// must stay where they are while it is in use.
class NearbyQueries {
 public:
  explicit NearbyQueries(const std::vector<RigidBody>& bodies);
  /// Body `body`'s closest surface point to p.
  SurfacePoint closest(int body, const Eigen::Vector3d& p);
  /// How far outside body `body` p lies at least, as the last answer about the body proves
  /// without a query: at q, outside by s, so by s − |p − q| or more at p (for a watertight body
  /// only); −∞ when it proves nothing.
  double clearance_bound(int body, const Eigen::Vector3d& p) const;
  /// Whether clearance_bound() exceeds `clearance`. False says nothing: ask closest().
  bool surely_outside(int body, const Eigen::Vector3d& p, double clearance) const {
    return clearance_bound(body, p) > clearance;
  }

 private:
  struct Answer {
    int triangle = -1;  // -1 before the body's first query
    Eigen::Vector3d at = Eigen::Vector3d::Zero();
    double signed_distance = 0.0;
  };
  const std::vector<RigidBody>* bodies_;
  std::vector<Answer> last_;  // per body
};

/// Calls visit(k, queries) for every k in [0, count), in parallel over runs of consecutive k
/// that share one NearbyQueries. Runs have a fixed length, so that no answer depends on the
/// thread count; visit must only write what belongs to its k.
void for_each_nearby(int count, const std::vector<RigidBody>& bodies,
                     const std::function<void(int, NearbyQueries&)>& visit);

}  // namespace fabform
