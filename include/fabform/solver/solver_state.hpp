#pragma once
// What every solver works on and hands back: where each node is and which body, if any, it
// rests on; and seed 003's measure ‖V‖∞ of that state (Eq. 6), which every solver reports so
// that their histories compare one to one.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

struct NodeContact {
  int body = -1;  // index into Model::bodies; -1 when free
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  // Where the node came onto the body: friction resists the node's slip from here.
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
  // A free node resting in a valley of the body (a concave crease, RigidBody::valley_normals)
  // has `normal` and this, its two faces' normals; zero elsewhere. Both faces hold it while its
  // force presses into both, and it moves only along the valley (equilibrium.hpp).
  Eigen::Vector3d crease = Eigen::Vector3d::Zero();
  bool active() const { return body >= 0; }
  const Eigen::Vector3d* crease_normal() const { return crease.isZero() ? nullptr : &crease; }
};

struct SolverState {
  std::vector<Eigen::Vector3d> x;
  std::vector<NodeContact> contact;
  // What a solver carries from one iteration to the next, kept here so that a checkpoint holds
  // all a resumed run needs to go on exactly as the uninterrupted run would have.
  std::vector<Eigen::Vector3d> velocity;  // dynamic's node velocities; empty: at rest
  double regularization = 0.0;            // newton's current μ; 0: its options' initial value

  static SolverState at_start(const Model& model);
};

/// Coulomb's μ between the fabric and the body a node rests on (0 when it rests on none).
double contact_friction(const Model& model, const NodeContact& contact);

/// V_k of one node placed at `at` (the others where `state` has them), in `contact`.
double node_residual(const Model& model, const SolverState& state, int node,
                     const Eigen::Vector3d& at, const NodeContact& contact);

struct StateResidual {
  double max_residual_N = 0.0;  // ‖V‖∞, NaN when a node is broken
  int worst_node = -1;          // where it is attained (or the first broken node)
  int contact_nodes = 0;        // nodes the state holds on a body
};

/// ‖V‖∞ with contact as the state records it. A node whose position is NaN or Inf is reported
/// first (NaN residual, that node), as the place where the state broke (not found by geometry: see measure_equilibrium).
StateResidual measure_state(const Model& model, const SolverState& state);

/// The same from each node's resultant R, already computed at the state's positions.
StateResidual measure_state(const Model& model, const SolverState& state,
                            const std::vector<Eigen::Vector3d>& forces);

}  // namespace fabform
