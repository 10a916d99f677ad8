#pragma once
// Coulomb friction for Newton's method, as incremental potential contact smooths and lags it
// (Li et al. 2020, "Incremental Potential Contact", §5): each node k on a body of friction μ
// adds D_k = μ·λ_k·f0(|u_k|), u_k = P_k·(x_k − a_k) its slip from its anchor a_k (where it came
// onto the body) within the tangent plane P_k, λ_k the force pressing it on the body. λ_k and
// P_k are lagged: taken at the Newton iteration's start and held while it searches, so D is a
// potential within the iteration, with an exact, positive semi-definite Hessian.
// f0 smooths |u| over a creep length ε: f0' = f1, f1(y) = 2y/ε − y²/ε² below ε and 1 beyond.
// A node that slipped less than ε is stuck, held by a spring of stiffness up to 2μλ/ε; one that
// slipped farther slides against a force μλ opposed to its slip. The slip is measured over the
// whole solve, as IPC measures it over one time step: friction opposes a node's displacement
// since it landed, not the last iteration's (Newton's iterates are no physical path, and
// following them made a capstan band's nodes stick that a monotone pull slides). So one solve
// is one load step: a node that slides and then sticks needs the history of several.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/term.hpp"
#include "fabform/solver/solver_state.hpp"

namespace fabform {

struct FrictionContact {
  int node = -1;
  double limit_N = 0.0;    // μ·λ, the largest force friction holds
  Eigen::Vector3d normal;  // the body's normal: friction acts in the plane across it
  Eigen::Vector3d anchor;  // where the node came onto the body
};

class LaggedFriction final : public Term {
 public:
  LaggedFriction(std::vector<FrictionContact> contacts, double creep_m, int node_count);

  bool empty() const { return contacts_.empty(); }

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;

 private:
  const FrictionContact* contact_of(int node) const;
  Eigen::Vector3d slip(const FrictionContact& c, const Eigen::Vector3d& at) const;
  double node_energy(const FrictionContact& c, const Eigen::Vector3d& at) const;

  std::vector<FrictionContact> contacts_;
  double creep_m_;
  std::vector<int> slot_;  // per node: its index in contacts_, or -1
};

/// The friction on every node `state` holds on a body with μ > 0 and pressed on it by `forces`
/// (each node's R without friction), lagged at `state`.
LaggedFriction lag_friction(const Model& model, const SolverState& state,
                            const std::vector<Eigen::Vector3d>& forces, double creep_m);

/// The creep length ε for a fraction of the fabric's mean spring length.
double friction_creep_m(const Model& model, double fraction);

}  // namespace fabform
