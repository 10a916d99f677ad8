#pragma once
// Coulomb friction between the fabric and the bodies, for Newton's method: the smoothed
// potential of coulomb_friction.hpp on every node a body holds, with the force pressing it on
// (λ) and the body's normal lagged: taken at the Newton iteration's start and held while it
// searches, so that friction is a potential within the iteration, with an exact, positive
// semi-definite Hessian. Each node's anchor is where it came onto the body (NodeContact): the
// slip is measured over the whole solve, as IPC measures it over one time step, so one solve
// (one load step) is one increment; a node that slides and then sticks needs several steps.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/coulomb_friction.hpp"
#include "fabform/solver/solver_state.hpp"

namespace fabform {

/// The friction on every node `state` holds on a body with μ > 0 and pressed on it by `forces`
/// (each node's R without friction), lagged at `state`.
CoulombFriction lag_friction(const Model& model, const SolverState& state,
                             const std::vector<Eigen::Vector3d>& forces, double creep_m);

}  // namespace fabform
