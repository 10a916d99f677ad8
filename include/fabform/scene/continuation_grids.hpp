#pragma once
// Which coarser grids a scene is solved on first (grid continuation: the scene's own grid then
// starts near its rest, run/coarse_grid_start.hpp): each halves the one above, the scene's
// solver.continuation_levels of them, or as many as fabform chooses when it gives none.
#include <array>
#include <string>
#include <vector>

#include "fabform/scene/scene.hpp"

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

}  // namespace fabform
