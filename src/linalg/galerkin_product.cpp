#include "linalg/galerkin_product.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "fabform/thread_count.hpp"

namespace fabform {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// One coarse row's sums, over the columns it reaches; reused from row to row by one thread.
class RowAccumulator {
 public:
  explicit RowAccumulator(Eigen::Index columns) : value_(static_cast<std::size_t>(columns)), seen_(value_.size(), -1) {}

  /// Row c of R A P into the accumulator: Σ_u r_cu Σ_v a_uv p_v·, in the order of R's, A's and
  /// P's entries. Its columns are then `columns()`, ascending.
  void sum(const RowMatrix& r, const RowMatrix& a, const RowMatrix& p, Eigen::Index c) {
    columns_.clear();
    for (RowMatrix::InnerIterator ru(r, c); ru; ++ru)
      for (RowMatrix::InnerIterator av(a, ru.col()); av; ++av) {
        const double weight = ru.value() * av.value();
        for (RowMatrix::InnerIterator pv(p, av.col()); pv; ++pv) {
          const auto column = static_cast<std::size_t>(pv.col());
          if (seen_[column] != c) {
            seen_[column] = c;
            value_[column] = 0.0;
            columns_.push_back(static_cast<int>(column));
          }
          value_[column] += weight * pv.value();
        }
      }
    std::sort(columns_.begin(), columns_.end());
  }
  const std::vector<int>& columns() const { return columns_; }
  double value(int column) const { return value_[static_cast<std::size_t>(column)]; }

 private:
  std::vector<double> value_;
  std::vector<Eigen::Index> seen_;  // the row that last wrote each column
  std::vector<int> columns_;
};

}  // namespace

RowMatrix galerkin_product(const RowMatrix& restriction, const RowMatrix& a, const RowMatrix& prolongation) {
  if (a.rows() != a.cols() || restriction.cols() != a.rows() || prolongation.rows() != a.rows() ||
      restriction.rows() != prolongation.cols())
    throw std::invalid_argument("galerkin_product: R, A and P do not chain");
  const Eigen::Index rows = restriction.rows();
  RowMatrix coarse(rows, prolongation.cols());
  // Twice over the rows: their lengths first, so that each row is then written in its place.
  std::vector<int> start(static_cast<std::size_t>(rows) + 1, 0);
  const bool parallel = rows >= kMinParallelItems;
#pragma omp parallel if (parallel)
  {
    RowAccumulator row(prolongation.cols());
#pragma omp for schedule(dynamic, 256)
    for (Eigen::Index c = 0; c < rows; ++c) {
      row.sum(restriction, a, prolongation, c);
      start[static_cast<std::size_t>(c) + 1] = static_cast<int>(row.columns().size());
    }
  }
  for (std::size_t c = 0; c < static_cast<std::size_t>(rows); ++c) start[c + 1] += start[c];
  coarse.resizeNonZeros(start.back());
  std::copy(start.begin(), start.end(), coarse.outerIndexPtr());
#pragma omp parallel if (parallel)
  {
    RowAccumulator row(prolongation.cols());
#pragma omp for schedule(dynamic, 256)
    for (Eigen::Index c = 0; c < rows; ++c) {
      row.sum(restriction, a, prolongation, c);
      int at = start[static_cast<std::size_t>(c)];
      for (const int column : row.columns()) {
        coarse.innerIndexPtr()[at] = column;
        coarse.valuePtr()[at++] = row.value(column);
      }
    }
  }
  return coarse;
}

}  // namespace fabform
