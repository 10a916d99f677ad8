#pragma once
// The diagonal of a large sparse matrix, read and written on every thread. Eigen finds each
// diagonal entry by a search of its outer vector on one thread: on the dome at N = 401, reading
// Newton's matrix's diagonal (and writing it back regularised) and the line smoother's mean
// diagonal were 938 of the 6 060 samples the main thread ran while the other waited. Each entry is found
// the same way, so the values are Eigen's, bit for bit, on any number of threads.
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace fabform {

/// Where a matrix stores its diagonal entries: per row (= column), the entry's
/// index in its value array, or −1 where none is stored.
template <int Options>
std::vector<Eigen::Index> diagonal_positions(const Eigen::SparseMatrix<double, Options>& m);

/// The stored diagonal entries (0 where none is), as `m.diagonal()` reads it.
template <int Options>
Eigen::VectorXd stored_diagonal(const Eigen::SparseMatrix<double, Options>& m,
                                const std::vector<Eigen::Index>& positions);

/// Writes d + shift onto the stored diagonal, whose every entry must be stored.
template <int Options>
void set_shifted_diagonal(Eigen::SparseMatrix<double, Options>& m, const std::vector<Eigen::Index>& positions,
                          const Eigen::VectorXd& d, double shift);

/// The sum of a vector's entries from first to last, one after another: the order Eigen sums
/// a sparse matrix's diagonal in (a dense vector's sum() is vectorised, in another order).
double sum_in_order(const Eigen::VectorXd& v);

}  // namespace fabform
