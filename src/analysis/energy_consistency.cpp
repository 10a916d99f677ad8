#include "fabform/analysis/energy_consistency.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fabform/model/potential_energy.hpp"

namespace fabform {
namespace {

constexpr double kMoveM = 1e-9;
constexpr double kDisagreeShare = 0.5;

// Half the difference of the changes `change(at)` makes at x ± δ·direction.
template <class Change>
double central_change(const Positions& x, int node, const Eigen::Vector3d& direction, const Change& change) {
  const Eigen::Vector3d& here = x[static_cast<std::size_t>(node)];
  const Eigen::Vector3d move = kMoveM * direction;
  return 0.5 * (change(Eigen::Vector3d(here + move)) - change(Eigen::Vector3d(here - move)));
}

// The term whose energy change along `direction` differs most from what its force predicts.
std::string worst_term(const Model& model, const Positions& x, int node, const Eigen::Vector3d& direction) {
  std::string worst;
  double largest = -1.0;
  for (const auto& term : model.terms) {
    const double predicted =
        -term->force_at(model, x, node, x[static_cast<std::size_t>(node)]).dot(direction) * kMoveM;
    const double measured = central_change(
        x, node, direction, [&](const Eigen::Vector3d& at) { return term->node_energy_change(model, x, node, at); });
    if (std::abs(measured - predicted) > largest) {
      largest = std::abs(measured - predicted);
      worst = term->describe(model);
    }
  }
  return worst.substr(0, worst.find(':'));
}

}  // namespace

EnergyConsistency check_energy_consistency(const Model& model, const SolverState& state) {
  if (model.solver_needs().contains(SolverNeed::velocity))
    throw std::invalid_argument("the model has a force that depends on velocity (wind's drag), which has no energy to check");
  const std::vector<Eigen::Vector3d> forces = node_forces(model, state.x);
  EnergyConsistency result;
  for (int k = 0; k < model.node_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (state.contact[i].active()) continue;  // a node on a body moves along it, not along R
    Eigen::Vector3d force = forces[i];
    for (int axis = 0; axis < 3; ++axis)
      if (model.locks[i] & (1 << axis)) force[axis] = 0.0;
    if (!(force.norm() > kSmallestForceN)) continue;
    ++result.checked;
    const Eigen::Vector3d direction = force.normalized();
    EnergyDisagreement d{k, force.norm(), -force.norm() * kMoveM, 0.0, ""};
    d.measured_J = central_change(state.x, k, direction, [&](const Eigen::Vector3d& at) {
      return node_energy_change(model, state.x, k, at);
    });
    if (std::abs(d.measured_J - d.predicted_J) <= kDisagreeShare * std::abs(d.predicted_J)) continue;
    d.term = worst_term(model, state.x, k, direction);
    result.disagreeing.push_back(d);
  }
  std::sort(result.disagreeing.begin(), result.disagreeing.end(),
            [](const EnergyDisagreement& a, const EnergyDisagreement& b) {
              return std::abs(a.measured_J - a.predicted_J) > std::abs(b.measured_J - b.predicted_J);
            });
  return result;
}

}  // namespace fabform
