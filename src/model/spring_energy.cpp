#include "fabform/model/spring_energy.hpp"

#include <algorithm>

namespace fabform {

Vector6d spring_gradient(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                         const Spring& spring, const TensionTable& table) {
  const Eigen::Vector3d on_a = spring_force_on_a(xa, xb, spring, table);
  Vector6d gradient;
  gradient << -on_a, on_a;
  return gradient;
}

Eigen::Matrix3d projected_spring_stiffness(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                           const Spring& spring, const TensionTable& table, double slack_axial) {
  SpringStiffness k = spring_stiffness_parts(xa, xb, spring, table);
  if (k.axial <= 0.0) k.axial = slack_axial;  // (a NaN stays, for the run to report)
  k.transverse = std::max(k.transverse, 0.0);
  return k.matrix();
}

Matrix6d spring_hessian_from(const Eigen::Matrix3d& stiffness) {
  Matrix6d hessian;
  hessian << stiffness, -stiffness, -stiffness, stiffness;
  return hessian;
}

Matrix6d spring_hessian(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, const Spring& spring,
                        const TensionTable& table) {
  return spring_hessian_from(spring_stiffness(xa, xb, spring, table));
}

}  // namespace fabform
