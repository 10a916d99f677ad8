#include "linalg/block_gauss_seidel.hpp"

#include <stdexcept>
#include <utility>

#include <Eigen/Eigenvalues>

#include "fabform/thread_count.hpp"

namespace fabform {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// A pseudo-inverse: no move along a direction the block has no stiffness along (a coarse point
// no finer unknown reaches).
Eigen::Matrix3d pseudo_inverse(const Eigen::Matrix3d& block) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(block);
  const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
  Eigen::Vector3d inverted = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (eigen.eigenvalues()[k] > 1e-12 * largest) inverted[k] = 1.0 / eigen.eigenvalues()[k];
  return eigen.eigenvectors() * inverted.asDiagonal() * eigen.eigenvectors().transpose();
}

std::vector<Eigen::Matrix3d> block_inverses(const RowMatrix& a, const std::vector<int>& start) {
  std::vector<Eigen::Matrix3d> inverse(start.size() - 1);
#pragma omp parallel for schedule(static) if (inverse.size() >= kMinParallelItems)
  for (std::size_t b = 0; b < inverse.size(); ++b) {
    const int s = start[b], m = start[b + 1] - s;
    Eigen::Matrix3d block = Eigen::Matrix3d::Zero();
    for (int r = 0; r < m; ++r)
      for (int p = a.outerIndexPtr()[s + r]; p < a.outerIndexPtr()[s + r + 1]; ++p)
        if (const int c = a.innerIndexPtr()[p] - s; c >= 0 && c < m) block(r, c) = a.valuePtr()[p];
    inverse[b] = pseudo_inverse(block);
  }
  return inverse;
}

}  // namespace

BlockGaussSeidel::BlockGaussSeidel(const RowMatrix& a, std::vector<int> block_start)
    : block_start_(std::move(block_start)) {
  if (block_start_.empty() || block_start_.back() != a.rows())
    throw std::invalid_argument("BlockGaussSeidel: the blocks do not cover the matrix");
  for (std::size_t b = 0; b + 1 < block_start_.size(); ++b)
    if (block_start_[b + 1] - block_start_[b] > 3 || block_start_[b + 1] < block_start_[b])
      throw std::invalid_argument("BlockGaussSeidel: a node with more than 3 unknowns, or blocks out of order");
  inverse_ = block_inverses(a, block_start_);
}

// The node's unknowns from the others' current values: x_b = B⁻¹ (b − Σ_{j ∉ node} a_bj x_j).
void BlockGaussSeidel::relax(const RowMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x, int block) const {
  const int s = block_start_[static_cast<std::size_t>(block)], e = block_start_[static_cast<std::size_t>(block) + 1];
  const int* row_start = a.outerIndexPtr();
  const int* column = a.innerIndexPtr();
  const double* value = a.valuePtr();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int i = s; i < e; ++i) {
    double sum = b[i];
    for (int p = row_start[i]; p < row_start[i + 1]; ++p)
      if (column[p] < s || column[p] >= e) sum -= value[p] * x[column[p]];
    r[i - s] = sum;
  }
  const Eigen::Vector3d solved = inverse_[static_cast<std::size_t>(block)] * r;
  for (int i = s; i < e; ++i) x[i] = solved[i - s];
}

void BlockGaussSeidel::sweep(const RowMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x, bool forward) const {
  const int blocks = static_cast<int>(inverse_.size());
  for (int t = 0; t < blocks; ++t) relax(a, b, x, forward ? t : blocks - 1 - t);
}

}  // namespace fabform
