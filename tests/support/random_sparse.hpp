#pragma once
// Random sparse test matrices: each row `per_row` entries at random columns (repeats summed),
// values in [−1, 1]; with `empty_every` > 0, every row r with r % empty_every == empty_every − 1
// left empty (shapes with empty rows and columns).
#include <algorithm>
#include <random>
#include <vector>

#include <Eigen/SparseCore>

namespace fabform::test {

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

}  // namespace fabform::test
