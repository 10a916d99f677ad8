#include "linalg/galerkin_product.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

#include <omp.h>

#include "fabform/thread_count.hpp"
#include "linalg/parallel_failure.hpp"

namespace fabform {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Each thread's accumulators and each block sit on cache lines of their own: a vector's end
// moves with every entry pushed, and two threads pushing into neighbours on one line would take
// it from each other at every entry.
constexpr std::size_t kCacheLine = 64;

// A row under construction: its entries' values in a dense array, the columns met in a list.
struct alignas(kCacheLine) SparseAccumulator {
  std::vector<double> value;
  std::vector<char> present;
  std::vector<int> columns;

  explicit SparseAccumulator(Eigen::Index size)
      : value(static_cast<std::size_t>(size), 0.0), present(static_cast<std::size_t>(size), 0) {}

  void add(int column, double v) {
    const auto c = static_cast<std::size_t>(column);
    if (!present[c]) {
      columns.push_back(column);  // first: a failed push leaves the accumulator as it was
      present[c] = 1;
      value[c] = v;
    } else {
      value[c] += v;
    }
  }
  // The entry's value, cleared.
  double take(int column) {
    const auto c = static_cast<std::size_t>(column);
    present[c] = 0;
    return value[c];
  }
};

// Consecutive rows of a row-major matrix.
struct alignas(kCacheLine) RowBlock {
  std::vector<int> row_size, column;
  std::vector<double> value;
};

// Row k of R A, then that row times P, into `out`.
void product_row(const RowMatrix& r, const RowMatrix& a, const RowMatrix& p, Eigen::Index k,
                 SparseAccumulator& fine, SparseAccumulator& coarse, RowBlock& out) {
  for (RowMatrix::InnerIterator rk(r, k); rk; ++rk)
    for (RowMatrix::InnerIterator aj(a, rk.col()); aj; ++aj) fine.add(static_cast<int>(aj.col()), rk.value() * aj.value());
  // In increasing order, as Eigen's products sum: the same bits as theirs.
  std::sort(fine.columns.begin(), fine.columns.end());
  for (const int j : fine.columns) {
    const double raj = fine.take(j);
    for (RowMatrix::InnerIterator pl(p, j); pl; ++pl) coarse.add(static_cast<int>(pl.col()), raj * pl.value());
  }
  fine.columns.clear();
  std::sort(coarse.columns.begin(), coarse.columns.end());
  for (const int l : coarse.columns) {
    out.column.push_back(l);
    out.value.push_back(coarse.take(l));
  }
  out.row_size.push_back(static_cast<int>(coarse.columns.size()));
  coarse.columns.clear();
}

// The blocks' rows one after another, each block copied on its own thread.
RowMatrix stacked(const std::vector<RowBlock>& blocks, Eigen::Index rows, Eigen::Index columns, int threads) {
  std::vector<Eigen::Index> first(blocks.size() + 1, 0);  // per block: its first entry
  for (std::size_t k = 0; k < blocks.size(); ++k) first[k + 1] = first[k] + static_cast<Eigen::Index>(blocks[k].value.size());
  if (first.back() > std::numeric_limits<int>::max())
    throw std::length_error("galerkin_product: more entries than Eigen's int indices hold");
  RowMatrix out(rows, columns);
  out.resizeNonZeros(first.back());
  std::vector<Eigen::Index> first_row(blocks.size() + 1, 0);
  for (std::size_t k = 0; k < blocks.size(); ++k)
    first_row[k + 1] = first_row[k] + static_cast<Eigen::Index>(blocks[k].row_size.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const RowBlock& b = blocks[k];
    Eigen::Index row = first_row[k], at = first[k];
    for (const int size : b.row_size) {
      out.outerIndexPtr()[row++] = static_cast<int>(at);
      at += size;
    }
    std::copy(b.column.begin(), b.column.end(), out.innerIndexPtr() + first[k]);
    std::copy(b.value.begin(), b.value.end(), out.valuePtr() + first[k]);
  }
  out.outerIndexPtr()[rows] = static_cast<int>(first.back());
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
  std::vector<RowBlock> blocks(static_cast<std::size_t>(count));
  // Each thread sums into its own accumulators (each as long as A's rows), made before the loop
  // so that no allocation can fail inside it but a row's, which is caught there. After one, the
  // blocks left are skipped.
  const int threads = std::max(1, std::min(threads_in_use(), count));
  std::vector<SparseAccumulator> fine, coarse;
  for (int t = 0; t < threads; ++t) {
    fine.emplace_back(a.cols());
    coarse.emplace_back(prolongation.cols());
  }
  ParallelFailure failure;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int k = 0; k < count; ++k) {
    if (failure.caught()) continue;
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const Eigen::Index first = k * block_rows, end = std::min(rows, first + block_rows);
    try {
      RowBlock& block = blocks[static_cast<std::size_t>(k)];
      for (Eigen::Index row = first; row < end; ++row)
        product_row(restriction, a, prolongation, row, fine[t], coarse[t], block);
    } catch (...) {
      failure.capture();
    }
  }
  failure.rethrow();
  return stacked(blocks, rows, prolongation.cols(), threads);
}

}  // namespace fabform
