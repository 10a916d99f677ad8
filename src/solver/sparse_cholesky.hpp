#pragma once
// The Newton solver's sparse Cholesky: CHOLMOD's supernodal factorisation (through Eigen's
// RAII wrapper, which owns CHOLMOD's workspace), whose dense kernels run on one OpenBLAS thread
// (thread_count.hpp).
// It is several times faster than a simplicial factorisation on fabric grids, whose factors
// fill in to dense fronts. The pattern is analysed (ordered) only when it differs from the last
// one, which within a Newton solve it never does (free_directions.hpp).
#include <memory>
#include <optional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace fabform {

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Analyses the pattern of `lower` (the lower triangle of a symmetric matrix) when it differs
  /// from the last one analysed, then factorises; false when the matrix is not positive definite.
  bool factorize(Eigen::SparseMatrix<double> lower);

  /// x with A x = b for the matrix last factorised successfully.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fabform
