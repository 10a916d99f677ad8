#pragma once
// Conjugate gradients preconditioned by a symmetric positive definite operator, from x = 0:
// every iterate lowers ½x'Ax − b'x, so x is a descent direction for any b ≠ 0 however early it
// stops.
#include <functional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace fabform {

struct CgResult {
  Eigen::VectorXd x;
  int iterations = 0;
  double relative_residual = 0.0;  // ‖b − A x‖₂ / ‖b‖₂
};

using Preconditioner = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

/// x with ‖b − A x‖₂ ≤ relative_tolerance · ‖b‖₂, or the last iterate after `max_iterations`;
/// `a` is the whole symmetric matrix.
CgResult preconditioned_cg(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                           const Preconditioner& precondition, double relative_tolerance, int max_iterations);

}  // namespace fabform
