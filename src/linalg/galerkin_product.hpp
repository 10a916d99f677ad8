#pragma once
// A multigrid level's matrix, the Galerkin product PᵀAP, a block of coarse rows at a time: only
// one block's PᵀA is held at once (on a million nodes the whole PᵀA was the hierarchy's largest
// temporary). A row is summed as Eigen sums it whatever the blocks, so the bits are those of the
// whole product.
#include <Eigen/SparseCore>

namespace fabform {

/// Coarse rows a block: its R A is the temporary (about 60 MB on the finest level of a million
/// nodes, against the whole PᵀA's 0.7 GB). Each block's product also clears a mask as long as
/// A's rows, so blocks much smaller cost more. The blocks' products are held until they are
/// stacked, so the coarse matrix is held twice for a moment.
constexpr Eigen::Index kGalerkinBlockRows = 65536;

/// R A P, with R = Pᵀ given by rows (the cycle keeps it to restrict with); `a` square.
Eigen::SparseMatrix<double, Eigen::RowMajor> galerkin_product(const Eigen::SparseMatrix<double, Eigen::RowMajor>& restriction,
                                                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                                                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& prolongation,
                                                              Eigen::Index block_rows = kGalerkinBlockRows);

}  // namespace fabform
