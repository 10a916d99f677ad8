#pragma once
// The math of one spring, apart from any simulation state: a spring of rest length L and
// width w stretched between xa and xb to strain ε = |xb − xa|/L − 1 carries the force
// f = w·T(ε) along itself (seed 003: S_k = σ(ε)·A_k with A_k the cross-section, here
// tension per width × width) and stores the energy E = w·L·∫₀^ε T.
#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/material/tension_table.hpp"

namespace fabform {

double spring_strain(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, double rest_length);

double spring_energy(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, const Spring& spring,
                     const TensionTable& table);

/// Force the spring exerts on node a (the force on b is its negative). Zero for coincident
/// nodes, where the spring has no direction.
Eigen::Vector3d spring_force_on_a(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                  const Spring& spring, const TensionTable& table);

/// The spring's stiffness K = ∂²E/∂xa² split along and across its direction u:
/// K = axial·uuᵀ + transverse·(I − uuᵀ), axial = w·T'(ε)/L, transverse = w·T(ε)/l.
struct SpringStiffness {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // u, from a to b
  double axial = 0.0;       // N/m
  double transverse = 0.0;  // N/m
  Eigen::Matrix3d matrix() const;
};

/// Both parts zero for coincident nodes, where the spring has no direction.
SpringStiffness spring_stiffness_parts(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                       const Spring& spring, const TensionTable& table);

/// ∂²E/∂xa² (3 × 3); the full Hessian is [[K, −K], [−K, K]]. Exact, not projected.
Eigen::Matrix3d spring_stiffness(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                 const Spring& spring, const TensionTable& table);

}  // namespace fabform
