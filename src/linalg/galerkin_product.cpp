#include "linalg/galerkin_product.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace fabform {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// The blocks' rows one after another.
RowMatrix stacked(const std::vector<RowMatrix>& blocks, Eigen::Index columns) {
  Eigen::Index rows = 0, entries = 0;
  for (const RowMatrix& b : blocks) {
    rows += b.rows();
    entries += b.nonZeros();
  }
  RowMatrix out(rows, columns);
  out.resizeNonZeros(entries);
  Eigen::Index row = 0, at = 0;
  for (const RowMatrix& b : blocks) {
    for (Eigen::Index r = 0; r < b.rows(); ++r) out.outerIndexPtr()[row + r] = static_cast<int>(at + b.outerIndexPtr()[r]);
    std::copy(b.innerIndexPtr(), b.innerIndexPtr() + b.nonZeros(), out.innerIndexPtr() + at);
    std::copy(b.valuePtr(), b.valuePtr() + b.nonZeros(), out.valuePtr() + at);
    row += b.rows();
    at += b.nonZeros();
  }
  out.outerIndexPtr()[rows] = static_cast<int>(at);
  return out;
}

}  // namespace

RowMatrix galerkin_product(const RowMatrix& restriction, const RowMatrix& a, const RowMatrix& prolongation,
                           Eigen::Index block_rows) {
  if (a.rows() != a.cols() || restriction.cols() != a.rows() || prolongation.rows() != a.rows() ||
      restriction.rows() != prolongation.cols())
    throw std::invalid_argument("galerkin_product: R, A and P do not chain");
  if (block_rows < 1) throw std::invalid_argument("galerkin_product: blocks of no rows");
  const Eigen::Index rows = restriction.rows();
  const auto count = static_cast<int>(rows == 0 ? 0 : (rows - 1) / block_rows + 1);
  std::vector<RowMatrix> blocks(static_cast<std::size_t>(count));
  // On one thread: on two, the blocks' products (each allocating its temporaries afresh) took
  // the dome at N = 1001 from 181 s to 216 s.
  for (int k = 0; k < count; ++k) {
    const Eigen::Index first = k * block_rows, size = std::min(block_rows, rows - first);
    const RowMatrix ra = restriction.middleRows(first, size) * a;
    blocks[static_cast<std::size_t>(k)] = ra * prolongation;
  }
  return stacked(blocks, prolongation.cols());
}

}  // namespace fabform
