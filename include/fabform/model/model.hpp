#pragma once
// Everything a solver needs, in SI, validated: the fabric and the tables of its springs, the
// per-node axis locks, the rigid bodies, the starting positions, and the physical terms that
// act on the fabric (term.hpp). A model starts with its fabric's springs as terms; a scene adds
// what else it asks for (hinges, weight, wind, ...).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/fabric/node_set.hpp"
#include "fabform/geometry/rigid_body.hpp"
#include "fabform/geometry/tool_path.hpp"
#include "fabform/material/tension_table.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

/// Friction against a body needs stick; a spring wrapped over an edge, a step no time step bounds.
constexpr SolverNeeds kBodyFrictionNeeds = SolverNeed::stick;
constexpr SolverNeeds kWrappedEdgeNeeds = SolverNeed::no_time_step;

struct NeedingPart {
  std::string name;
  SolverNeeds needs;
};

struct Model {
  /// A model of the fabric's springs alone: stretch (warp and weft), and shear and bend springs
  /// where the fabric has them (their tables, `shear` and `bend`, are then the caller's to set).
  Model(Fabric fabric, TensionTable warp, TensionTable weft, std::vector<AxisMask> locks,
        std::vector<RigidBody> bodies, std::vector<Eigen::Vector3d> start);

  Fabric fabric;
  TensionTable warp;
  TensionTable weft;
  std::vector<AxisMask> locks;  // one per node
  std::vector<RigidBody> bodies;
  std::vector<Eigen::Vector3d> start;  // one per node
  double areal_density_kg_m2 = 0.0;         // the fabric's, when its weight is modelled; else 0
  std::optional<TensionTable> shear = {};   // the shear springs' table, when the fabric has them
  std::optional<TensionTable> bend = {};    // the bend springs' table, when the fabric has them
  TermList terms;                           // every term acting on the fabric, springs first
  std::vector<ToolPath> paths;              // none, or one per body: its travel (steps 0: it stays put)
  std::vector<std::string> read_warnings;   // what reading the inputs skipped, tolerated or found implausible

  /// The table a kind of spring follows; the model builder makes sure the fabric's kinds have one.
  const TensionTable& table(SpringKind kind) const {
    switch (kind) {
      case SpringKind::warp: return warp;
      case SpringKind::weft: return weft;
      case SpringKind::shear: return shear.value();
      case SpringKind::bend: return bend.value();
    }
    return warp;
  }
  int node_count() const { return fabric.node_count(); }

  /// Each term, said in one line, in the order the model holds them (result.json's "modelled").
  std::vector<std::string> modelled() const;
  /// Whether some term is an external load (a force that acts however the springs are set).
  bool loaded() const;
  /// Whether some term resists folding.
  bool resists_bending() const;
  /// Whether some body holds the fabric by friction.
  bool has_friction() const;
  /// Whether some body lets springs wrap its edges (spring_path.hpp).
  bool wraps_edges() const;
  /// Each part of the model that asks something of its solver, with what it asks: its terms, by
  /// the names they describe themselves with, friction against the bodies and springs wrapped
  /// over their edges (the solvers' own, not terms).
  std::vector<NeedingPart> parts_needing() const;
  /// What the model asks of the solver that solves it: every part's needs.
  SolverNeeds solver_needs() const;
  /// K, the load steps in which the bodies travel; 0 when none moves.
  int load_steps() const;
};

/// The model's terms of type T, in the model's order (the seams, the self-contact, ...).
template <class T>
std::vector<const T*> terms_of(const Model& model) {
  std::vector<const T*> found;
  for (const auto& term : model.terms)
    if (const auto* t = dynamic_cast<const T*>(term.get())) found.push_back(t);
  return found;
}

/// R at `node` with the node moved to `at` and every other node where `x` has it: the sum of
/// every term's force on it (for a velocity-dependent term, its force on the fabric at rest).
Eigen::Vector3d node_force_at(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at);

inline Eigen::Vector3d node_force(const Model& model, const Positions& x, int node) {
  return node_force_at(model, x, node, x[static_cast<std::size_t>(node)]);
}

/// R at every node at x: node_force at each, summed over the terms in the same order, each term
/// in one pass (Term::add_forces).
std::vector<Eigen::Vector3d> node_forces(const Model& model, const Positions& x);

}  // namespace fabform
