#pragma once
// The directions each node may move in during a Newton step: its free axes, less the normal of
// the body it presses on. Newton's unknowns are the node displacements along them, so locked
// axes and contact normals are eliminated from the system rather than penalised: a held
// coordinate cannot drift and a node on a body is not pushed into it.
// The unknowns' layout depends on the locks alone: a node has a slot per free axis, and a slot a
// contact normal takes away keeps a zero basis column (an empty row and column of Newton's
// matrix, whose solution there is exactly zero). So the matrix's pattern stays the same while
// nodes land on and leave bodies, and its fill-reducing ordering (AMD and METIS: about half of
// a Newton iteration's time on a 400 × 400 dome) is computed once per solve, not once per step.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"
#include "linalg/linear_solver.hpp"

namespace fabform {

struct FreeDirections {
  std::vector<int> offset;             // first unknown of each node; the last entry is the total
  std::vector<Eigen::Matrix3d> basis;  // per node: orthonormal columns, the rest zero
  int used = 0;                        // slots with a direction (a nonzero basis column)

  /// The node's slots: one per free axis, whether or not a contact normal has taken it.
  int count(int k) const { return offset[k + 1] - offset[k]; }
  int unknowns() const { return offset.back(); }
  /// Unused columns are zero, so basis * (reduced step) needs no size checks.
  const Eigen::Matrix3d& of(int k) const { return basis[static_cast<std::size_t>(k)]; }
};

FreeDirections free_directions(const Model& model, const std::vector<NodeContact>& contact);

/// Node displacements (3 per node, zero along eliminated directions) from Newton's unknowns.
std::vector<Eigen::Vector3d> node_steps(const FreeDirections& directions,
                                        const Eigen::VectorXd& unknowns);

/// What the linear solve may know of the unknowns: each one's place among its node's slots
/// (0, 1, 2: along x, y, z for a free node, and for the tangent directions of a node on a body
/// in the order of the axes they came from); and, where the fabric's nodes lie on a lattice
/// (not an arc mesh's rings and spokes), each one's node, lattice place and direction.
UnknownLayout unknown_layout(const FreeDirections& directions, const Fabric& fabric);

/// The node forces in Newton's unknowns: each node's force on its free directions.
Eigen::VectorXd reduced_forces(const FreeDirections& directions,
                               const std::vector<Eigen::Vector3d>& forces);

}  // namespace fabform
