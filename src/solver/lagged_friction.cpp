#include "solver/lagged_friction.hpp"

#include <utility>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/model.hpp"

namespace fabform {

CoulombFriction lag_friction(const Model& model, const SolverState& state,
                             const std::vector<Eigen::Vector3d>& forces, double creep_m) {
  std::vector<FrictionContact> contacts;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const NodeContact& contact = state.contact[k];
    const double mu = contact_friction(model, contact);
    const double pressing = pressing_force(forces[k], model.locks[k], contact.normal, contact.crease_normal());
    if (mu > 0.0 && pressing > 0.0)
      contacts.push_back({static_cast<int>(k), mu * pressing, contact.normal, contact.anchor});
  }
  return CoulombFriction(std::move(contacts), creep_m, model.node_count());
}

}  // namespace fabform
