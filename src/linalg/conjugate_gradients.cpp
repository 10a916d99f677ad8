#include "linalg/conjugate_gradients.hpp"

namespace fabform {

CgResult preconditioned_cg(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                           const Preconditioner& precondition, double relative_tolerance, int max_iterations) {
  CgResult result;
  result.x = Eigen::VectorXd::Zero(b.size());
  const double b_norm = b.norm();
  if (b_norm == 0.0) return result;
  Eigen::VectorXd r = b;
  Eigen::VectorXd z = precondition(r);
  Eigen::VectorXd p = z;
  Eigen::VectorXd ap(b.size());
  double rz = r.dot(z);
  double residual = b_norm;
  while (result.iterations < max_iterations && residual > relative_tolerance * b_norm) {
    ap.noalias() = a * p;
    const double curvature = p.dot(ap);
    if (!(curvature > 0.0)) break;  // rounding at a converged solve: the last iterate stands
    const double alpha = rz / curvature;
    result.x += alpha * p;
    r -= alpha * ap;
    residual = r.norm();
    ++result.iterations;
    if (residual <= relative_tolerance * b_norm) break;
    z = precondition(r);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  result.relative_residual = residual / b_norm;
  return result;
}

}  // namespace fabform
