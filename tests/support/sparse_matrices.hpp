#pragma once
// Sparse test matrices: random ones, and a comparison to the bit.
#include <algorithm>
#include <random>
#include <vector>

#include <Eigen/SparseCore>

namespace fabform::test {

/// Each row `per_row` entries at random columns (repeats summed), values in [−1, 1]; with
/// `empty_every` > 0, every row r with r % empty_every == empty_every − 1 left empty (shapes with
/// empty rows and columns).
inline Eigen::SparseMatrix<double, Eigen::RowMajor> random_sparse(Eigen::Index rows, Eigen::Index columns, int per_row,
                                                                  unsigned seed, int empty_every = 0) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<Eigen::Index> column(0, std::max<Eigen::Index>(columns - 1, 0));
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index r = 0; r < rows && columns > 0; ++r) {
    if (empty_every > 0 && r % empty_every == empty_every - 1) continue;
    for (int k = 0; k < per_row; ++k) entries.emplace_back(r, column(rng), value(rng));
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> m(rows, columns);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

/// The same shape, pattern and values, bit for bit, stored alike.
inline bool same_bits(const Eigen::SparseMatrix<double, Eigen::RowMajor>& x,
                      const Eigen::SparseMatrix<double, Eigen::RowMajor>& y) {
  return x.rows() == y.rows() && x.cols() == y.cols() && x.nonZeros() == y.nonZeros() &&
         std::equal(x.valuePtr(), x.valuePtr() + x.nonZeros(), y.valuePtr()) &&
         std::equal(x.innerIndexPtr(), x.innerIndexPtr() + x.nonZeros(), y.innerIndexPtr()) &&
         std::equal(x.outerIndexPtr(), x.outerIndexPtr() + x.rows() + 1, y.outerIndexPtr());
}

}  // namespace fabform::test
