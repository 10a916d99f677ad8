#pragma once
// Forces on the fabric that do not depend on where it is: its weight. They enter every node's
// resultant R (stretch_forces.hpp) and, as the potential −Σ f·x, the energy Newton's line
// search descends (potential_energy.hpp).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"

namespace fabform {

/// Standard gravity (m/s²), the default of a scene's [gravity].
constexpr double kStandardGravity_m_s2 = 9.80665;

/// The weight of each node, along −z: areal density × the node's area × g.
std::vector<Eigen::Vector3d> gravity_loads(const Fabric& grid, double areal_density_kg_m2,
                                           double acceleration_m_s2);

/// −Σ f_k · x_k (J): the potential of constant loads; 0 when there are none (`loads` empty).
double load_energy(const std::vector<Eigen::Vector3d>& loads, const std::vector<Eigen::Vector3d>& x);

/// −Σ f_k · (to_k − from_k) (J): the change of that potential, computed from the moves, so it
/// keeps its digits however high the fabric sits (a difference of two absolute potentials
/// would lose them to m·g·z).
double load_energy_change(const std::vector<Eigen::Vector3d>& loads, const std::vector<Eigen::Vector3d>& from,
                          const std::vector<Eigen::Vector3d>& to);

/// A warning when the tolerance e is not well below the lightest node's load (e ≥ 0.1 of it):
/// a run can then stop before the loads have had their effect. "" otherwise, or with no loads.
std::string load_tolerance_warning(const std::vector<Eigen::Vector3d>& loads, double tolerance_N);

}  // namespace fabform
