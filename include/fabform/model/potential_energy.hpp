#pragma once
// The fabric's total potential energy Π(x): the sum of its terms' potentials (term.hpp). The
// forces of model.hpp are −∂Π/∂x where every term has a potential; relax's fallback and
// Newton's line search ask Π to decrease.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// Π(x) (J): the energy the fabric stores plus the potential of its loads.
double potential_energy(const Model& model, const Positions& x);

/// Π at a state, term by term, from which changes of Π are measured.
struct EnergyBaseline {
  std::vector<double> of_term;  // Π_t(x), in the model's order
  double stored = 0.0;          // the sum over terms that are not external loads (J)
};
EnergyBaseline energy_baseline(const Model& model, const Positions& x);

/// Π(to) − Π(from), `baseline` being Π at `from`: each term's change its own way, so a load's
/// keeps its digits however high the fabric sits.
double energy_change(const Model& model, const Positions& from, const EnergyBaseline& baseline,
                     const Positions& to);

/// How much Π changes when `node` alone moves from x[node] to `at` (J).
double node_energy_change(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at);

}  // namespace fabform
