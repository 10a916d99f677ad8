#pragma once
// A multigrid level's matrix, the Galerkin product R A P (R = Pᵀ), computed row by row of R
// without a temporary matrix: each coarse row's R A row is summed into a dense accumulator as
// long as A's rows and at once multiplied by P into one as long as P's columns. Eigen's products
// cost twice over here: R A on a million nodes is a 0.7 GB temporary, and a row-major product
// sorts its result by converting it to column-major and back, which with the products themselves
// was a fifth of a Newton step on the dome at 401 × 401 nodes, all on one thread. From two blocks
// of coarse rows, the blocks are summed on every thread; a row is summed the same way whatever
// the blocks and threads, so the bits do not depend on them.
#include <Eigen/SparseCore>

namespace fabform {

/// Coarse rows a block: small enough for the blocks to share out evenly among threads on every
/// level but the coarsest two (a level of 7 803 rows, 51 × 51 points, was summed on one thread
/// with blocks of 4096 while the other waited), large enough that a block's work (about a
/// millisecond) dwarfs handing it out; each block's rows held apart until they are stacked (so
/// the coarse matrix is held twice for a moment).
constexpr Eigen::Index kGalerkinBlockRows = 1024;

/// R A P, with R = Pᵀ given by rows (the cycle keeps it to restrict with); `a` square. Each
/// row's columns in increasing order.
Eigen::SparseMatrix<double, Eigen::RowMajor> galerkin_product(const Eigen::SparseMatrix<double, Eigen::RowMajor>& restriction,
                                                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                                                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& prolongation,
                                                              Eigen::Index block_rows = kGalerkinBlockRows);

}  // namespace fabform
