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

/// How a free node meets a valley of a body (a concave crease, RigidBody::valley_normals): on
/// one face at a time, as seed 003 has it (relax and dynamic), or resting on both faces
/// (NodeContact::crease), a move along one face past the valley stopping in it: newton, whose
/// steps then keep it there (free_directions.hpp) instead of hopping from face to face.
enum class Valleys { one_face, both_faces };

/// Node `node`, at `from` with `contact`, moved by `step` (its locked components are dropped).
/// A node on a body should be given a step in its tangent plane.
NodeMove move_node(const Model& model, int node, const Eigen::Vector3d& from,
                   const Eigen::Vector3d& step, const NodeContact& contact, Valleys valleys = Valleys::one_face);

}  // namespace fabform
