#pragma once
// Grid continuation: newton solves the scene on its coarser grids first
// (scene/continuation_grids.hpp), each from the coarser rest interpolated
// (solver/grid_continuation.hpp), so that the scene's own grid starts near its rest.
#include <array>
#include <vector>

#include "fabform/model/model.hpp"
#include "fabform/scene/scene.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

struct ContinuationLevel {
  std::array<int, 2> divisions = {0, 0};
  Summary summary;  // the level's own solve
};

struct Continuation {
  SolverState start;                      // for the scene's own grid
  std::vector<ContinuationLevel> levels;  // coarsest first
};

/// Solves the scene's coarser grids (continuation_grids) and returns the start they give the
/// scene's own grid, `model` (built from `scene`, its tolerance in newtons). A level that does
/// not converge ends the continuation: the levels after it are not solved, and the grid starts
/// from the last converged rest (or, if none, its own start).
Continuation continue_from_coarse_grids(const Scene& scene, const Model& model);

}  // namespace fabform
