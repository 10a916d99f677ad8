#pragma once
// One spring as an element of the fabric's total potential energy Π(x) = Σ w·L·Ψ(ε), Ψ = ∫₀^ε T:
// its gradient and Hessian over its six coordinates (xa, xb), exact or projected to be positive
// semi-definite for Newton's method. The energy itself is spring_energy (fabric/spring.hpp).
#include <Eigen/Core>

#include "fabform/fabric/spring.hpp"

namespace fabform {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// [∂E/∂xa; ∂E/∂xb]: minus the forces the spring exerts on a and b.
Vector6d spring_gradient(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                         const Spring& spring, const TensionTable& table);

/// The nearest positive semi-definite stiffness of this form: the axial part uses T' clamped
/// at 0 (a softening table segment), the transverse part T/l clamped at 0 (a slack or
/// compressed spring buckles rather than resists turning). Where T' ≤ 0 the axial part is
/// `slack_axial` (N/m) instead: a step's matrix may keep a slack spring's nodes from
/// near-singular moves (StiffnessSink::slack_share); 0 keeps the clamp.
Eigen::Matrix3d projected_spring_stiffness(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                           const Spring& spring, const TensionTable& table,
                                           double slack_axial = 0.0);

/// [[K, −K], [−K, K]] from a 3 × 3 stiffness K; positive semi-definite exactly when K is.
Matrix6d spring_hessian_from(const Eigen::Matrix3d& stiffness);

/// The exact Hessian ∂²E/∂(xa, xb)².
Matrix6d spring_hessian(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, const Spring& spring,
                        const TensionTable& table);

}  // namespace fabform
