#include "fabform/run/coarse_grid_start.hpp"

#include <optional>
#include <utility>

#include "fabform/scene/continuation_grids.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/solver/grid_continuation.hpp"
#include "fabform/solver/solve.hpp"

namespace fabform {

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
