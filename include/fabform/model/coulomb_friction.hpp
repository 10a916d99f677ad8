#pragma once
// Coulomb friction as a potential, smoothed as incremental potential contact smooths it (Li et
// al. 2020, "Incremental Potential Contact", §5): each held node k adds D_k = F_k·f0(|u_k|),
// u_k = P_k·(x_k − a_k) its slip from its anchor a_k within the plane P_k across a normal n_k,
// F_k the largest force friction holds there (μ times the force pressing the node on).
// f0 smooths |u| over a creep length ε: f0' = f1, f1(y) = 2y/ε − y²/ε² below ε and 1 beyond.
// A node that slipped less than ε is stuck, held by a spring of stiffness up to 2F/ε; one that
// slipped farther slides against the force F opposed to its slip. The slip is measured from the
// anchor, not the last iterate: friction opposes a node's displacement since it was put there
// (Newton's iterates are no physical path, and following them made a capstan band's nodes
// stick that a monotone pull slides).
// Newton lags the contact with a body (solver/lagged_friction.hpp: F and n taken at each
// iteration's start); a blank holder's are fixed (clamp_frame.hpp).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/model/term.hpp"

namespace fabform {

struct FrictionContact {
  int node = -1;
  double limit_N = 0.0;    // F = μ·λ, the largest force friction holds
  Eigen::Vector3d normal;  // friction acts in the plane across it
  Eigen::Vector3d anchor;  // where the node was put: its slip is measured from here
};

class CoulombFriction final : public Term {
 public:
  CoulombFriction(std::vector<FrictionContact> contacts, double creep_m, int node_count);

  bool empty() const { return contacts_.empty(); }
  /// Whether `node` slipped less than ε from its anchor at `at` (false for a node it does not hold).
  bool stuck(int node, const Eigen::Vector3d& at) const;

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

/// The creep length ε for a fraction of the fabric's mean spring length.
double friction_creep_m(const Fabric& fabric, double fraction);

}  // namespace fabform
