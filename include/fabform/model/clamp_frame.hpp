#pragma once
// A blank holder, a term of the model: a frame presses the rim of the blank on to the die with
// a normal force, and the rim draws in under it once the pull exceeds the friction of both
// faces (holder and die), 2·μ·N_k at node k, N_k the node's share of the force by the fabric
// it stands for. The holder is horizontal: its nodes are held in z (the model builder locks
// them) and slide in x and y, resisted by the smoothed Coulomb potential of
// coulomb_friction.hpp with each node's anchor where it started. The force is fixed, so this
// is a true potential, not a lagged one; only newton minimises it (relax's rule has no stick,
// and its creep stiffness 2·2μN/ε would bound dynamic's time step).
#include <string>
#include <vector>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/coulomb_friction.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

struct ClampOptions {
  double force_N = 0.0;   // the holder's whole normal force
  double friction = 0.0;  // μ between the knit and the holder (and the die)
  double creep_m = 0.0;   // ε: a node that slipped less is stuck

  /// Why the options cannot be used, or ""; `field` gets the option's name.
  std::string invalid_reason(std::string* field = nullptr) const;
};

class ClampFrame final : public Term {
 public:
  /// `nodes` are the held ones (not empty), `start` every node's starting position.
  ClampFrame(const Fabric& fabric, std::vector<int> nodes, const ClampOptions& options, const Positions& start);

  const std::vector<int>& nodes() const { return nodes_; }
  /// Whether a held node slipped less than the creep length from where it started.
  bool stuck(int node, const Eigen::Vector3d& at) const { return friction_.stuck(node, at); }

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override {
    return friction_.force_at(model, x, node, at);
  }
  double energy(const Model& model, const Positions& x) const override { return friction_.energy(model, x); }
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override {
    return friction_.node_energy_change(model, x, node, at);
  }
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override {
    friction_.add_stiffness(model, x, sink);
  }
  /// What it needs of its solver; the scene reader asks the same of a scene that would have it.
  static constexpr SolverNeeds kNeeds = SolverNeed::stick | SolverNeed::stiff_penalty;
  SolverNeeds needs() const override { return kNeeds; }

 private:
  std::vector<int> nodes_;
  ClampOptions options_;
  CoulombFriction friction_;
};

}  // namespace fabform
