#include "fabform/solver/solver_state.hpp"

#include <cmath>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/model.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {

SolverState SolverState::at_start(const Model& model) {
  SolverState state;
  state.x = model.start;
  state.contact.resize(model.start.size());
  return state;
}

double contact_friction(const Model& model, const NodeContact& contact) {
  return contact.active() ? model.bodies[static_cast<std::size_t>(contact.body)].friction() : 0.0;
}

double node_residual(const Model& model, const SolverState& state, int node,
                     const Eigen::Vector3d& at, const NodeContact& contact) {
  const Eigen::Vector3d r = node_force_at(model, state.x, node, at);
  return unbalanced_force(r, model.locks[static_cast<std::size_t>(node)],
                          contact.active() ? &contact.normal : nullptr, contact_friction(model, contact),
                          contact.crease_normal())
      .norm();
}

namespace {

// A broken node decides the run: first one whose position is not finite (its neighbours'
// residuals follow from it), else the first whose residual is NaN.
StateResidual worst_of(const SolverState& state, const std::vector<double>& residual) {
  StateResidual m;
  int broken = -1;
  for (std::size_t i = 0; i < residual.size(); ++i) {
    const double v = residual[i];
    const int k = static_cast<int>(i);
    m.contact_nodes += state.contact[i].active() ? 1 : 0;
    if (!state.x[i].allFinite()) return {std::nan(""), k, m.contact_nodes};
    if (std::isnan(v) && broken < 0) broken = k;
    if (v > m.max_residual_N || m.worst_node < 0) m.max_residual_N = v, m.worst_node = k;
  }
  if (broken >= 0) m.max_residual_N = std::nan(""), m.worst_node = broken;
  return m;
}

}  // namespace

StateResidual measure_state(const Model& model, const SolverState& state) {
  return measure_state(model, state, node_forces(model, state.x));
}

StateResidual measure_state(const Model& model, const SolverState& state,
                            const std::vector<Eigen::Vector3d>& forces) {
  std::vector<double> residual(state.x.size());
  for (std::size_t i = 0; i < residual.size(); ++i) {
    const NodeContact& contact = state.contact[i];
    residual[i] = unbalanced_force(forces[i], model.locks[i], contact.active() ? &contact.normal : nullptr,
                                   contact_friction(model, contact), contact.crease_normal())
                      .norm();
  }
  return worst_of(state, residual);
}

}  // namespace fabform
