#include "fabform/solver/grid_continuation.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "fabform/geometry/nearby_queries.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/solver/solve.hpp"

namespace fabform {

std::vector<std::array<int, 2>> continuation_grids(const Scene& scene) {
  std::vector<std::array<int, 2>> grids;
  std::array<int, 2> d = {scene.fabric.divisions_warp, scene.fabric.divisions_weft};
  for (int level = 0; level < scene.solver.continuation_levels; ++level) {
    if (std::min(d[0], d[1]) / 2 < kMinContinuationDivisions) break;
    d = {d[0] / 2, d[1] / 2};
    grids.insert(grids.begin(), d);
  }
  return grids;
}

int chosen_continuation_levels(const Scene& scene) {
  std::array<int, 2> d = {scene.fabric.divisions_warp, scene.fabric.divisions_weft};
  int levels = 0;
  while (d[0] % 2 == 0 && d[1] % 2 == 0 && std::min(d[0], d[1]) / 2 >= kChosenCoarsestDivisions)
    d = {d[0] / 2, d[1] / 2}, ++levels;
  if (levels == 0) return 0;
  Scene continued = scene;
  continued.solver.continuation_levels = levels;
  std::string key;
  return continuation_refusal(continued, &key).empty() ? levels : 0;
}

namespace {

// The first division count on the way down that does not halve, or 0.
int odd_divisions(const Scene& scene) {
  std::array<int, 2> d = {scene.fabric.divisions_warp, scene.fabric.divisions_weft};
  for (int level = 0; level < scene.solver.continuation_levels; ++level) {
    if (std::min(d[0], d[1]) / 2 < kMinContinuationDivisions) return 0;
    for (const int n : d)
      if (n % 2 != 0) return n;
    d = {d[0] / 2, d[1] / 2};
  }
  return 0;
}

}  // namespace

std::string continuation_refusal(const Scene& scene, std::string* key) {
  *key = "continuation_levels";
  if (scene.solver.continuation_levels == 0) return "";
  if (scene.solver.name != "newton") {
    *key = "name";
    return "grid continuation (solver.continuation_levels) runs newton only, not " + scene.solver.name;
  }
  for (const BodySpec& body : scene.bodies)
    if (body.path.moves())
      return "body '" + body.name + "' travels in load steps ([body.path]); grid continuation solves one rest, not steps";
  if (scene.fabric.mesh == FabricSpec::Mesh::arc)
    return "an arc mesh (rings on spokes) has no coarser lattice: grid continuation is not supported for it";
  if (scene.fabric.shape == FabricSpec::Shape::panels)
    return "panels' boundary nodes lie on their outlines, which a coarser lattice would meet elsewhere: grid continuation is not supported for them";
  for (std::size_t c = 0; c < scene.constraints.size(); ++c)
    if (scene.constraints[c].nodes.kind == NodeSetSpec::Kind::index)
      return "constraint " + std::to_string(c) + " names a node by its lattice index, which means another place on a coarser grid";
  if (const int n = odd_divisions(scene); n != 0) return std::to_string(n) + " divisions do not halve";
  return "";
}

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

Continuation continue_from_coarse_grids(const Scene& scene, const Model& model) {
  Continuation result{SolverState::at_start(model), {}};
  std::optional<Fabric> coarse;
  std::vector<Eigen::Vector3d> coarse_rest;
  for (const std::array<int, 2>& divisions : continuation_grids(scene)) {
    Scene level_scene = scene;
    level_scene.fabric.divisions_warp = divisions[0];
    level_scene.fabric.divisions_weft = divisions[1];
    level_scene.solver.continuation_levels = 0;
    level_scene.solver.newton.final_estimate = false;
    const Model level = build_model(level_scene, &model);  // the mold read once, not per grid
    SolverState state = coarse ? continued_start(level, interpolate_rest(*coarse, coarse_rest, level.fabric))
                               : SolverState::at_start(level);
    Summary summary = solve(level, state, level_scene.solver, {},
                            begin_summary(scene.solver.name, scene.solver.tolerance_N(), {}, scene.solver.tolerance_m()));
    const bool converged = summary.converged();
    result.levels.push_back({divisions, std::move(summary)});
    if (!converged) break;
    coarse.emplace(level.fabric);
    coarse_rest = std::move(state.x);
  }
  if (coarse) result.start = continued_start(model, interpolate_rest(*coarse, coarse_rest, model.fabric));
  return result;
}

}  // namespace fabform
