#include "linalg/sparse_diagonal.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "fabform/thread_count.hpp"

namespace fabform {

template <int Options>
std::vector<Eigen::Index> diagonal_positions(const Eigen::SparseMatrix<double, Options>& m) {
  const Eigen::Index n = std::min(m.rows(), m.cols());
  std::vector<Eigen::Index> positions(static_cast<std::size_t>(n));
  const int* outer = m.outerIndexPtr();
  const int* inner = m.innerIndexPtr();
  const int* filled = m.innerNonZeroPtr();  // an uncompressed matrix's entries in each outer vector
#pragma omp parallel for schedule(static) if (n >= kMinParallelItems)
  for (Eigen::Index k = 0; k < n; ++k) {
    const int* end = inner + (filled ? outer[k] + filled[k] : outer[k + 1]);
    const int* found = std::lower_bound(inner + outer[k], end, static_cast<int>(k));
    positions[static_cast<std::size_t>(k)] = found != end && *found == k ? found - inner : -1;
  }
  return positions;
}

template <int Options>
Eigen::VectorXd stored_diagonal(const Eigen::SparseMatrix<double, Options>& m,
                                const std::vector<Eigen::Index>& positions) {
  const auto n = static_cast<Eigen::Index>(positions.size());
  Eigen::VectorXd d(n);
  const double* value = m.valuePtr();
#pragma omp parallel for schedule(static) if (n >= kMinParallelItems)
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index at = positions[static_cast<std::size_t>(k)];
    d[k] = at < 0 ? 0.0 : value[at];
  }
  return d;
}

template <int Options>
void set_shifted_diagonal(Eigen::SparseMatrix<double, Options>& m, const std::vector<Eigen::Index>& positions,
                          const Eigen::VectorXd& d, double shift) {
  const auto n = static_cast<Eigen::Index>(positions.size());
  if (d.size() != n) throw std::invalid_argument("set_shifted_diagonal: a value per diagonal entry is needed");
  if (std::find(positions.begin(), positions.end(), Eigen::Index{-1}) != positions.end())
    throw std::invalid_argument("set_shifted_diagonal: a diagonal entry is not stored");
  double* value = m.valuePtr();
#pragma omp parallel for schedule(static) if (n >= kMinParallelItems)
  for (Eigen::Index k = 0; k < n; ++k) value[positions[static_cast<std::size_t>(k)]] = d[k] + shift;
}

double sum_in_order(const Eigen::VectorXd& v) { return std::accumulate(v.data(), v.data() + v.size(), 0.0); }

template std::vector<Eigen::Index> diagonal_positions(const Eigen::SparseMatrix<double, Eigen::ColMajor>&);
template std::vector<Eigen::Index> diagonal_positions(const Eigen::SparseMatrix<double, Eigen::RowMajor>&);
template Eigen::VectorXd stored_diagonal(const Eigen::SparseMatrix<double, Eigen::ColMajor>&,
                                         const std::vector<Eigen::Index>&);
template Eigen::VectorXd stored_diagonal(const Eigen::SparseMatrix<double, Eigen::RowMajor>&,
                                         const std::vector<Eigen::Index>&);
template void set_shifted_diagonal(Eigen::SparseMatrix<double, Eigen::ColMajor>&, const std::vector<Eigen::Index>&,
                                   const Eigen::VectorXd&, double);
template void set_shifted_diagonal(Eigen::SparseMatrix<double, Eigen::RowMajor>&, const std::vector<Eigen::Index>&,
                                   const Eigen::VectorXd&, double);

}  // namespace fabform
