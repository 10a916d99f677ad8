#pragma once
// Grid continuation's step from one grid to the next: a coarse rest interpolated onto a finer
// lattice with the same outline, and the start it gives the finer model (the grids and the solves
// in turn: scene/continuation_grids.hpp, run/coarse_grid_start.hpp).
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"

namespace fabform {

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

}  // namespace fabform
