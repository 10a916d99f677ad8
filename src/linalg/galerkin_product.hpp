#pragma once
// A multigrid level's matrix, the Galerkin product R A P (R = Pᵀ), computed row by row of R
// without a temporary matrix: each coarse row's R A row is summed into a dense accumulator as
// long as A's rows and at once multiplied by P into one as long as P's columns. Eigen's products
// cost twice over here: R A on a million nodes is a 0.7 GB temporary, and a row-major product
// sorts its result by converting it to column-major and back, which with the products themselves
// was a fifth of a Newton step on the dome at 401 × 401 nodes, all on one thread. From 8192 coarse
// rows, blocks of them are summed on every thread; a row is summed the same way whatever the
// blocks and threads, so the bits do not depend on them.
#include <Eigen/SparseCore>

namespace fabform {

/// Coarse rows a block: small enough for the blocks to share out evenly among threads on the
/// large levels, each block's rows held apart until they are stacked (so the coarse matrix is
/// held twice for a moment).
constexpr Eigen::Index kGalerkinBlockRows = 4096;

/// R A P, with R = Pᵀ given by rows (the cycle keeps it to restrict with); `a` square. Each
/// row's columns in increasing order.
Eigen::SparseMatrix<double, Eigen::RowMajor> galerkin_product(const Eigen::SparseMatrix<double, Eigen::RowMajor>& restriction,
                                                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                                                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& prolongation,
                                                              Eigen::Index block_rows = kGalerkinBlockRows);

}  // namespace fabform
