#pragma once
// The fabric's total potential energy Π(x): what every conservative term of the model stores.
// The forces of stretch_forces.hpp are −∂Π/∂x; Newton's line search asks Π to decrease.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// Stretch energy plus the potential of the external loads (J).
double potential_energy(const Model& model, const std::vector<Eigen::Vector3d>& x);

/// The part of Π that depends on `node`, with the node moved to `at`: the energy of its springs
/// and the potential of its load (J). Moving one node changes Π by exactly the change of this.
double node_energy_at(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                      const Eigen::Vector3d& at);

}  // namespace fabform
