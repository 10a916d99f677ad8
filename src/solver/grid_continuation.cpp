#include "fabform/solver/grid_continuation.hpp"

#include <cmath>
#include <limits>

#include "fabform/geometry/nearby_queries.hpp"

namespace fabform {

namespace {

// The coarse lattice's node at (i, j), or -1 outside it.
int coarse_node(const Fabric& coarse, int i, int j) {
  if (i < 0 || j < 0 || i >= coarse.nodes_warp() || j >= coarse.nodes_weft()) return -1;
  return coarse.node(i, j);
}

// The coarse node nearest lattice point (u, v), for a fine node beyond every coarse cell.
int nearest_coarse_node(const Fabric& coarse, double u, double v) {
  int best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < coarse.node_count(); ++k) {
    const double d2 = std::pow(coarse.i_of(k) - u, 2) + std::pow(coarse.j_of(k) - v, 2);
    if (d2 < best_d2) best = k, best_d2 = d2;
  }
  return best;
}

}  // namespace

std::vector<Eigen::Vector3d> interpolate_rest(const Fabric& coarse, const std::vector<Eigen::Vector3d>& coarse_x,
                                              const Fabric& fine) {
  const double ratio_i = static_cast<double>(fine.spec().divisions_warp) / coarse.spec().divisions_warp;
  const double ratio_j = static_cast<double>(fine.spec().divisions_weft) / coarse.spec().divisions_weft;
  const auto displacement = [&](int k) {
    return (coarse_x[static_cast<std::size_t>(k)] - coarse.rest_position(k)).eval();
  };
  std::vector<Eigen::Vector3d> x(static_cast<std::size_t>(fine.node_count()));
  for (int k = 0; k < fine.node_count(); ++k) {
    const double u = fine.i_of(k) / ratio_i, v = fine.j_of(k) / ratio_j;
    const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
    const double a = u - i0, b = v - j0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double weights = 0.0;
    const int corners[4][2] = {{i0, j0}, {i0 + 1, j0}, {i0, j0 + 1}, {i0 + 1, j0 + 1}};
    const double w[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
    for (int c = 0; c < 4; ++c) {
      const int n = coarse_node(coarse, corners[c][0], corners[c][1]);
      if (n < 0 || w[c] == 0.0) continue;
      sum += w[c] * displacement(n);
      weights += w[c];
    }
    const Eigen::Vector3d d = weights > 0.0 ? (sum / weights).eval() : displacement(nearest_coarse_node(coarse, u, v));
    x[static_cast<std::size_t>(k)] = fine.rest_position(k) + d;
  }
  return x;
}

SolverState continued_start(const Model& model, std::vector<Eigen::Vector3d> interpolated) {
  SolverState state = SolverState::at_start(model);
  NearbyQueries queries(model.bodies);
  for (int k = 0; k < model.node_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    const AxisMask locks = model.locks[i];
    Eigen::Vector3d p = interpolated[i];
    for (int axis = 0; axis < 3; ++axis)
      if (locks & (1 << axis)) p[axis] = model.start[i][axis];
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      // A node on a facet to within rounding starts on it, as on the coarse grid. Left free, the
      // first Newton step saw no surface under it, moved it in and was cut short where it landed:
      // 16 000 nodes at N = 1001, most of them let go again in the next steps.
      const double on_surface = model.bodies[b].on_surface_distance();
      if (queries.surely_outside(static_cast<int>(b), p, on_surface)) continue;
      const SurfacePoint s = queries.closest(static_cast<int>(b), p);
      if (s.signed_distance > on_surface) continue;
      // A free node goes onto the surface, resting there as on the coarse grid; a held one
      // cannot be moved off its held axes, so it keeps the start the builder checked clear.
      if (locks == 0) {
        p = s.point;
        state.contact[i] = NodeContact{static_cast<int>(b), s.normal, s.point};
      } else {
        p = model.start[i];
        state.contact[i] = NodeContact{};
      }
    }
    state.x[i] = p;
  }
  return state;
}

}  // namespace fabform
