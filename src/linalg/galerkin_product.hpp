#pragma once
// A multigrid level's matrix, the Galerkin product PᵀAP, one coarse row at a time: each row is
// summed in an accumulator over the coarse columns, so neither PᵀA nor AP is ever held (on a
// million nodes PᵀA was the hierarchy's largest temporary), and rows are shared among the
// threads. Each row is summed in the same order whatever the thread count, so the bits are too.
#include <Eigen/SparseCore>

namespace fabform {

/// R A P, with R = Pᵀ given by rows (the cycle keeps it to restrict with); `a` square.
Eigen::SparseMatrix<double, Eigen::RowMajor> galerkin_product(const Eigen::SparseMatrix<double, Eigen::RowMajor>& restriction,
                                                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                                                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& prolongation);

}  // namespace fabform
