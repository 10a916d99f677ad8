#include "fabform/model/potential_energy.hpp"

#include <cstddef>

#include "fabform/fabric/spring.hpp"
#include "fabform/model/external_loads.hpp"
#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/stretch_forces.hpp"

namespace fabform {

double elastic_energy(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  return stretch_energy(model, x) + bending_energy(model, x);
}

double potential_energy(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  return elastic_energy(model, x) + load_energy(model.loads, x);
}

namespace {

// The energy of the springs at `node` with the node at `at`.
double node_spring_energy(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                          const Eigen::Vector3d& at) {
  double energy = 0.0;
  for (const int s : model.fabric.springs_at(node)) {
    const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
    const Eigen::Vector3d& other = x[static_cast<std::size_t>(spring.a == node ? spring.b : spring.a)];
    energy += spring.a == node ? spring_energy(at, other, spring, model.table(spring.kind))
                               : spring_energy(other, at, spring, model.table(spring.kind));
  }
  return energy;
}

}  // namespace

double node_energy_change(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                          const Eigen::Vector3d& at) {
  const auto k = static_cast<std::size_t>(node);
  double change = node_spring_energy(model, x, node, at) - node_spring_energy(model, x, node, x[k]) +
                  node_bending_energy(model, x, node, at) - node_bending_energy(model, x, node, x[k]);
  if (!model.loads.empty()) change -= model.loads[k].dot(at - x[k]);
  return change;
}

}  // namespace fabform
