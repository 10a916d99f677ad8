#pragma once
// How a node moves among the rigid bodies (seed 003 §3.2.2–3.2.3), shared by every solver that
// moves nodes: a free node moves straight and stops on the surface where it would enter a body;
// a node on a body slides and is projected back onto the surface; locked axes never change.
#include <Eigen/Core>

#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"

namespace fabform {

struct NodeMove {
  Eigen::Vector3d x;
  NodeContact contact;
};

/// Node `node`, at `from` with `contact`, moved by `step` (its locked components are dropped).
/// A node on a body should be given a step in its tangent plane.
NodeMove move_node(const Model& model, int node, const Eigen::Vector3d& from,
                   const Eigen::Vector3d& step, const NodeContact& contact);

}  // namespace fabform
