#pragma once
// The fabric's total potential energy Π(x): what every conservative term of the model stores.
// The forces of stretch_forces.hpp are −∂Π/∂x; Newton's line search asks Π to decrease.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// The energy the fabric stores: its springs' and its hinges' (J).
double elastic_energy(const Model& model, const std::vector<Eigen::Vector3d>& x);

/// Elastic energy plus the potential of the external loads (J).
double potential_energy(const Model& model, const std::vector<Eigen::Vector3d>& x);

/// How much Π changes when `node` alone moves from x[node] to `at` (J): its springs' and
/// hinges' energy change and the work against its load. The load's part is −f·(at − x), not a difference of
/// −f·x at two absolute heights, so it does not depend on where the scene sits.
double node_energy_change(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                          const Eigen::Vector3d& at);

}  // namespace fabform
