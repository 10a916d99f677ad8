#include "fabform/model/potential_energy.hpp"

#include <cstddef>

namespace fabform {

double potential_energy(const Model& model, const Positions& x) {
  double energy = 0.0;
  for (const auto& term : model.terms) energy += term->energy(model, x);
  return energy;
}

EnergyBaseline energy_baseline(const Model& model, const Positions& x) {
  EnergyBaseline baseline;
  for (const auto& term : model.terms) {
    baseline.of_term.push_back(term->energy(model, x));
    if (!term->external()) baseline.stored += baseline.of_term.back();
  }
  return baseline;
}

double energy_change(const Model& model, const Positions& from, const EnergyBaseline& baseline,
                     const Positions& to) {
  double change = 0.0;
  for (std::size_t t = 0; t < model.terms.size(); ++t)
    change += model.terms[t]->energy_change(model, from, baseline.of_term[t], to);
  return change;
}

double node_energy_change(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) {
  double change = 0.0;
  for (const auto& term : model.terms) change += term->node_energy_change(model, x, node, at);
  return change;
}

}  // namespace fabform
