#pragma once
// The Newton solver's sparse Cholesky: CHOLMOD's supernodal factorisation, several times faster
// than a simplicial one on fabric grids, whose factors fill in to dense fronts. A matrix of
// 300 000 unknowns or more is split in two by a separator (substructured_cholesky.hpp), whose
// sides factorise on two threads; a smaller one, or one that does not split, is factorised
// whole. Dense kernels run on one OpenBLAS thread (thread_count.hpp), so the bits do not depend
// on the thread count. The pattern is analysed (ordered, split) only when it differs from the
// last one, which within a Newton solve it never does (free_directions.hpp).
#include <memory>
#include <optional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace fabform {

class SparseCholesky {
 public:
  /// Patterns of at least `min_split_unknowns` are split (SubstructuredCholesky::kMinUnknowns).
  explicit SparseCholesky(int min_split_unknowns);
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Analyses the pattern of `lower` (the lower triangle of a symmetric matrix) when it differs
  /// from the last one analysed, then factorises; false when the matrix is not positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& lower);

  /// x with A x = b for the matrix last factorised successfully.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  /// Whether the pattern last analysed was split in two (substructured_cholesky.hpp).
  bool split() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fabform
