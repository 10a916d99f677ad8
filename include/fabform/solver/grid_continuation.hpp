#pragma once
// Grid continuation (issue 23, item 2): newton solves the scene on grids coarsened by 2, 4, ...
// first, each from the coarser rest interpolated, so that the scene's own grid starts near its
// rest (issue 23 measured by hand: the dome at N = 401 from N = 201's rest, 17 iterations, not 49).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/model.hpp"
#include "fabform/scene/scene.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

// Below this many divisions a grid no longer resolves the scene's shape: no coarser level is made.
constexpr int kMinContinuationDivisions = 8;
// fabform's own choice coarsens no further than this many divisions: on the dome a coarser start
// saves less than its solve costs (the shipped dome, N = 201: 4.15 s with none, 2.06 s with two
// levels, to 50 divisions; docs/speed.md "Multigrid instead of the factorisation").
constexpr int kChosenCoarsestDivisions = 50;

/// The levels fabform chooses for a scene that gives none: as many halvings as keep both
/// divisions even and the coarsest grid at kChosenCoarsestDivisions or more, where the scene can
/// be continued at all (continuation_refusal); else 0.
int chosen_continuation_levels(const Scene& scene);

/// The divisions (warp, weft) of the coarser grids to solve, coarsest first; empty when
/// solver.continuation_levels is 0 or the grid is too small to coarsen. The scene must be
/// one continuation_refusal() accepts.
std::vector<std::array<int, 2>> continuation_grids(const Scene& scene);

/// Why the scene cannot be solved with grid continuation, and the key (dotted, in `*key`) to
/// blame; "" when it can or when solver.continuation_levels is 0.
std::string continuation_refusal(const Scene& scene, std::string* key);

/// The fine fabric's positions from a coarse rest on a lattice with the same outline: each fine
/// node takes the coarse displacement (position less flat position) interpolated bilinearly at
/// its place in the coarse lattice, added to its own flat position. Where a circle's rim leaves
/// some of the four coarse corners out, the others' weights are renormalised (none: the
/// nearest coarse node's displacement).
std::vector<Eigen::Vector3d> interpolate_rest(const Fabric& coarse, const std::vector<Eigen::Vector3d>& coarse_x,
                                              const Fabric& fine);

/// A start for `model` from interpolated positions: held axes keep the model's start; a free
/// node that lands in or on a body (within RigidBody::on_surface_distance) is put on its surface, in
/// contact (as in the coarse rest); a node held on some axis that lands inside a body keeps its
/// own start.
SolverState continued_start(const Model& model, std::vector<Eigen::Vector3d> interpolated);

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
