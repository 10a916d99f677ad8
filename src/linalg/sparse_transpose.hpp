#pragma once
// Transposes of sparse matrices on every thread. Eigen's conversions between storage orders,
// and its expansion of a symmetric matrix's lower triangle to the whole, run on one thread:
// on the dome at a million nodes, each Newton step's expansion of the finest matrix and
// transposes of the prolongations were the largest serial part of the multigrid's set-up.
// Each thread scatters the entries of its own band of outer vectors (rows of a row-major matrix,
// columns of a column-major one) into places counted for it in advance, so the result is the
// same, bit for bit and entry for entry, on any number of threads: Eigen's.
#include <Eigen/SparseCore>

namespace fabform {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// Aᵀ, each row's columns in increasing order.
RowMatrix transposed(const RowMatrix& a);

/// The whole symmetric matrix whose lower triangle `lower` holds (entries above its diagonal
/// ignored), each row's columns in increasing order: what `lower.selfadjointView<Eigen::Lower>()`
/// assigned to a row-major matrix gives.
RowMatrix whole_symmetric(const Eigen::SparseMatrix<double>& lower);

}  // namespace fabform
