#pragma once
// A spring wrapped over a body's edge (edge_wrap.hpp) as an element of the fabric's energy: its
// length is the path's, ℓ = |a − p| + |p − b| with p the point of the edge that makes it least, and
// it stores w·L·Ψ(ℓ/L − 1) as a straight spring of that length would. Because p is where ℓ is
// least, ∂ℓ/∂a is the unit vector from p to a (the envelope theorem): the spring pulls each node
// towards p, and the edge takes the rest. The Hessian is exact: ℓ is the least over p of a
// function convex in (a, b, p), so it is convex, and its Hessian is the Schur complement that
// lets p slide along the edge (held, when p is at an end of the edge).
#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/geometry/edge_wrap.hpp"
#include "fabform/material/tension_table.hpp"
#include "fabform/model/spring_energy.hpp"

namespace fabform {

double wrapped_spring_energy(const EdgeWrap& wrap, const Spring& spring, const TensionTable& table);

/// The force the wrapped spring exerts on the node at `node` (either end): w·T(ε) towards p.
Eigen::Vector3d wrapped_spring_force(const Eigen::Vector3d& node, const EdgeWrap& wrap, const Spring& spring,
                                     const TensionTable& table);

/// ∂²E/∂(xa, xb)². Projected: T and T' clamped at 0, positive semi-definite for Newton's method;
/// exact otherwise.
Matrix6d wrapped_spring_hessian(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, const EdgeWrap& wrap,
                                const Spring& spring, const TensionTable& table, bool projected);

}  // namespace fabform
