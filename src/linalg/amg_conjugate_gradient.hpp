#pragma once
// hypre, wrapped once: conjugate gradients preconditioned by one V-cycle of BoomerAMG, the
// algebraic multigrid whose cost grows linearly with the unknowns where a sparse Cholesky's
// fill grows as their 1.5th power on a fabric grid. hypre runs here on one MPI process (MPI is
// started on first use and finished at exit) and on one thread (Debian builds it without
// OpenMP). hypre's error codes become std::runtime_error; MPI that cannot start, a SystemError.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "linalg/conjugate_gradients.hpp"

namespace fabform {

class AmgConjugateGradient {
 public:
  AmgConjugateGradient();
  ~AmgConjugateGradient();
  AmgConjugateGradient(const AmgConjugateGradient&) = delete;
  AmgConjugateGradient& operator=(const AmgConjugateGradient&) = delete;

  /// Takes a symmetric positive definite matrix, given by its lower triangle with every
  /// diagonal entry stored, and builds its multigrid hierarchy. `component` gives each unknown's
  /// place in its node's displacement (0, 1, 2): unknowns of one component are coarsened
  /// together, hypre's "unknown" approach to systems such as elasticity.
  void set_matrix(const Eigen::SparseMatrix<double>& lower, const std::vector<int>& component);

  /// x with ‖b − A x‖₂ ≤ relative_tolerance · ‖b‖₂, from x = 0, in at most `max_iterations`; the
  /// last iterate when that many do not reach it. Every iterate lowers ½x'Ax − b'x, so x is a
  /// descent direction for any b ≠ 0 however loose the tolerance.
  CgResult solve(const Eigen::VectorXd& b, double relative_tolerance, int max_iterations) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fabform
