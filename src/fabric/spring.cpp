#include "fabform/fabric/spring.hpp"

namespace fabform {

double spring_strain(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, double rest_length) {
  return (xb - xa).norm() / rest_length - 1.0;
}

double spring_energy(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, const Spring& spring,
                     const TensionTable& table) {
  const double strain = spring_strain(xa, xb, spring.rest_length);
  return spring.width * spring.rest_length * table.energy_density(strain, spring.rest_length);
}

Eigen::Vector3d spring_force_on_a(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                  const Spring& spring, const TensionTable& table) {
  const Eigen::Vector3d d = xb - xa;
  const double length = d.norm();
  if (length == 0.0) return Eigen::Vector3d::Zero();
  const double strain = length / spring.rest_length - 1.0;
  return (spring.width * table.tension(strain, spring.rest_length) / length) * d;
}

Eigen::Matrix3d SpringStiffness::matrix() const {
  const Eigen::Matrix3d uu = direction * direction.transpose();
  return axial * uu + transverse * (Eigen::Matrix3d::Identity() - uu);
}

SpringStiffness spring_stiffness_parts(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                       const Spring& spring, const TensionTable& table) {
  const Eigen::Vector3d d = xb - xa;
  const double length = d.norm();
  if (length == 0.0) return {Eigen::Vector3d::UnitX(), 0.0, 0.0};
  const double strain = length / spring.rest_length - 1.0;
  return {d / length, spring.width * table.slope(strain, spring.rest_length) / spring.rest_length,
          spring.width * table.tension(strain, spring.rest_length) / length};
}

Eigen::Matrix3d spring_stiffness(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                 const Spring& spring, const TensionTable& table) {
  return spring_stiffness_parts(xa, xb, spring, table).matrix();
}

}  // namespace fabform
