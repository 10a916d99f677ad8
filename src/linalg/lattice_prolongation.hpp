#pragma once
// The interpolation between a fabric lattice and the lattice of every second node along each
// direction: bilinear in the lattice indices, so that a displacement smooth over the fabric is
// represented on the coarser lattice, the out-of-plane one included, which algebraic coarsening
// by strength of connection misses on a membrane (its out-of-plane stiffness is the tension's,
// orders of magnitude below the in-plane one).
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace fabform {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// Newton's unknowns on a fabric whose nodes lie on a lattice: each moves one node along one
/// direction in space.
struct LatticeUnknowns {
  std::array<int, 2> lattice_size = {0, 0};       // nodes along i and along j
  std::vector<std::array<int, 2>> node_lattice;   // per node: (i, j)
  std::vector<int> node;                          // per unknown: the node it moves
  std::vector<Eigen::Vector3d> direction;         // per unknown: its direction (zero: unused slot)
};

/// The coarser lattice's size: every second index along each direction, and the last one.
std::array<int, 2> coarser_lattice(std::array<int, 2> size);

/// Displacements of a whole lattice (3 per lattice point, point i + size[0]·j) from those of
/// its coarser lattice.
RowMatrix lattice_prolongation(std::array<int, 2> size);

/// Newton's unknowns from the displacements of the coarser lattice of theirs: each unknown is
/// the interpolated displacement of its node along its direction.
RowMatrix unknown_prolongation(const LatticeUnknowns& unknowns);

}  // namespace fabform
