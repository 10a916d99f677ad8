#pragma once
// Geometric multigrid on the fabric's lattice, as the preconditioner of conjugate gradients.
// The first coarser level is the lattice of every second node, reached from Newton's unknowns
// (each a node's move along one free direction: contact normals and locked axes are left out)
// by interpolating the coarse lattice's displacements bilinearly and projecting them on those
// directions; coarser levels halve the lattice again, down to a few hundred nodes, factorised.
// Each level's matrix is the Galerkin product PᵀAP (galerkin_product.hpp), so the contact
// constraints and the membrane's out-of-plane stiffness are carried down the hierarchy. Line
// Gauss–Seidel smoothing (line_gauss_seidel.hpp), forward before the coarse correction and
// backward after, keeps the V-cycle symmetric positive definite, as conjugate gradients require.
#include <cstddef>
#include <deque>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "linalg/conjugate_gradients.hpp"
#include "linalg/lattice_prolongation.hpp"
#include "linalg/line_gauss_seidel.hpp"

namespace fabform {

class LatticeMultigrid {
 public:
  /// Takes a symmetric positive definite matrix, by its lower triangle with every diagonal entry
  /// stored, over `unknowns`, and builds the hierarchy.
  void set_matrix(const Eigen::SparseMatrix<double>& lower, const LatticeUnknowns& unknowns);

  /// As AmgConjugateGradient::solve: to ‖b − A x‖₂ ≤ relative_tolerance · ‖b‖₂, from x = 0.
  CgResult solve(const Eigen::VectorXd& b, double relative_tolerance, int max_iterations) const;

  /// One V-cycle on b, from zero: the preconditioner.
  Eigen::VectorXd v_cycle(const Eigen::VectorXd& b) const;

  /// Levels including the finest and the factorised coarsest (0 before set_matrix).
  int levels() const { return static_cast<int>(levels_.size()) + (levels_.empty() ? 0 : 1); }

 private:
  struct Level {
    RowMatrix a;  // whole and symmetric
    LineGaussSeidel smoother;
    RowMatrix prolongation;  // from the next coarser level
    RowMatrix restriction;   // its transpose
  };
  Eigen::VectorXd cycle(std::size_t level, const Eigen::VectorXd& b) const;

  std::deque<Level> levels_;  // never moved: see set_matrix
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> coarsest_;
};

}  // namespace fabform
