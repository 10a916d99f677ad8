#include "fabform/model/wrapped_spring.hpp"

#include <algorithm>

namespace fabform {
namespace {

double path_strain(const EdgeWrap& wrap, const Spring& spring) { return wrap.length / spring.rest_length - 1.0; }

}  // namespace

double wrapped_spring_energy(const EdgeWrap& wrap, const Spring& spring, const TensionTable& table) {
  return spring.width * spring.rest_length * table.energy_density(path_strain(wrap, spring), spring.rest_length);
}

Eigen::Vector3d wrapped_spring_force(const Eigen::Vector3d& node, const EdgeWrap& wrap, const Spring& spring,
                                     const TensionTable& table) {
  const Eigen::Vector3d to_edge = wrap.point - node;
  const double distance = to_edge.norm();
  if (distance == 0.0) return Eigen::Vector3d::Zero();
  return (spring.width * table.tension(path_strain(wrap, spring), spring.rest_length) / distance) * to_edge;
}

Matrix6d wrapped_spring_hessian(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, const EdgeWrap& wrap,
                                const Spring& spring, const TensionTable& table, bool projected) {
  const double strain = path_strain(wrap, spring);
  double tension = spring.width * table.tension(strain, spring.rest_length);                        // dE/dℓ
  double slope = spring.width * table.slope(strain, spring.rest_length) / spring.rest_length;       // d²E/dℓ²
  if (projected) tension = std::max(tension, 0.0), slope = std::max(slope, 0.0);
  const double ra = (xa - wrap.point).norm(), rb = (xb - wrap.point).norm();
  Matrix6d hessian = Matrix6d::Zero();
  if (ra == 0.0 || rb == 0.0) return hessian;
  const Eigen::Vector3d ua = (xa - wrap.point) / ra, ub = (xb - wrap.point) / rb;
  Vector6d gradient;
  gradient << ua, ub;
  // ℓ's Hessian with p held: each leg's transverse stiffness (I − uuᵀ)/r.
  const Eigen::Matrix3d pa = (Eigen::Matrix3d::Identity() - ua * ua.transpose()) / ra;
  const Eigen::Matrix3d pb = (Eigen::Matrix3d::Identity() - ub * ub.transpose()) / rb;
  Matrix6d length_hessian = Matrix6d::Zero();
  length_hessian.topLeftCorner<3, 3>() = pa;
  length_hessian.bottomRightCorner<3, 3>() = pb;
  // Less what p's slide along the edge gives back: m·mᵀ / (∂²ℓ/∂s²), m = ∂²ℓ/∂x∂s.
  const double slide_stiffness = wrap.axis.dot(pa * wrap.axis) + wrap.axis.dot(pb * wrap.axis);
  if (!wrap.at_end && slide_stiffness > 0.0) {
    Vector6d coupling;
    coupling << pa * wrap.axis, pb * wrap.axis;
    length_hessian -= coupling * coupling.transpose() / slide_stiffness;
  }
  hessian = slope * gradient * gradient.transpose() + tension * length_hessian;
  return hessian;
}

}  // namespace fabform
