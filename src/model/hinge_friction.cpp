#include "fabform/model/hinge_friction.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/model.hpp"
#include "fabform/model/rounded_abs.hpp"

namespace fabform {
namespace {

double side_length(const Model& model, const Hinge& hinge) { return flat_side(model, hinge).norm(); }

// ρ'(|k|)/|k|: the gradient of ρ(|k|) with respect to k is this times k.
double rounded_slope_over_norm(double norm, double rounding) {
  return norm < rounding ? 1.0 / rounding : rounded_abs_slope(norm, rounding) / norm;
}

}  // namespace

HingeFriction::HingeFriction(double hysteresis_warp_N, double hysteresis_weft_N, double rounding_per_m)
    : hysteresis_warp_N_(hysteresis_warp_N), hysteresis_weft_N_(hysteresis_weft_N), rounding_per_m_(rounding_per_m) {
  if (!(hysteresis_warp_N >= 0.0 && hysteresis_weft_N >= 0.0 && rounding_per_m > 0.0))
    throw std::invalid_argument("hinge friction: 2HB must be non-negative and the rounding curvature positive");
}

double HingeFriction::friction_moment_of(const Model& model, const Hinge& hinge) const {
  return 0.5 * along_bending_direction(model, hinge, hysteresis_warp_N_, hysteresis_weft_N_);
}

double HingeFriction::rounding_angle_of(const Model& model, const Hinge& hinge) const {
  return rounding_per_m_ * side_length(model, hinge) / (2.0 * hinge.shape_factor);
}

double HingeFriction::friction_energy(const Model& model, const Hinge& hinge, const Positions& x, int moved,
                                      const Eigen::Vector3d& at) const {
  const double norm = bend_vector(hinge, x, moved, at).norm();
  return friction_moment_of(model, hinge) * side_length(model, hinge) *
         rounded_abs(norm, rounding_angle_of(model, hinge));
}

std::string HingeFriction::describe(const Model& model) const {
  char text[320];
  std::snprintf(text, sizeof text,
                "bending friction: hinges across %zu face sides bend against half the measured hysteresis 2HB "
                "(loading branch; 2HB %.6g N·m/m along the warp, %.6g N·m/m along the weft, rounded over %.6g 1/m)",
                model.fabric.hinges().size(), hysteresis_warp_N_, hysteresis_weft_N_, rounding_per_m_);
  return text;
}

double HingeFriction::energy(const Model& model, const Positions& x) const {
  double energy = 0.0;
  for (const Hinge& h : model.fabric.hinges()) energy += friction_energy(model, h, x, -1, Eigen::Vector3d::Zero());
  return energy;
}

Eigen::Vector3d HingeFriction::force_at(const Model& model, const Positions& x, int node,
                                        const Eigen::Vector3d& at) const {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const int i : model.fabric.hinges_at(node)) {
    const Hinge& h = model.fabric.hinges()[static_cast<std::size_t>(i)];
    const HingeStencil stencil = hinge_stencil(h);
    const Eigen::Vector3d k = bend_vector(h, x, node, at);
    const double slope = rounded_slope_over_norm(k.norm(), rounding_angle_of(model, h));
    force -= friction_moment_of(model, h) * side_length(model, h) * slope *
             stencil.weight[stencil_index(stencil, node)] * k;
  }
  return force;
}

double HingeFriction::node_energy_change(const Model& model, const Positions& x, int node,
                                         const Eigen::Vector3d& at) const {
  double change = 0.0;
  for (const int i : model.fabric.hinges_at(node)) {
    const Hinge& h = model.fabric.hinges()[static_cast<std::size_t>(i)];
    change += friction_energy(model, h, x, node, at) -
              friction_energy(model, h, x, node, x[static_cast<std::size_t>(node)]);
  }
  return change;
}

void HingeFriction::add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const {
  const std::vector<Hinge>& hinges = model.fabric.hinges();
  sink.add_each(hinges.size(), [&](std::size_t i, StiffnessSink& part) {
    const Hinge& h = hinges[i];
    const HingeStencil stencil = hinge_stencil(h);
    const Eigen::Vector3d k = bend_vector(h, x, -1, Eigen::Vector3d::Zero());
    const double norm = k.norm(), rounding = rounding_angle_of(model, h);
    Eigen::Matrix3d d = Eigen::Matrix3d::Identity() * rounded_slope_over_norm(norm, rounding);
    if (norm >= rounding) d -= k * k.transpose() / (norm * norm * norm);
    const double scale = friction_moment_of(model, h) * side_length(model, h);
    for (std::size_t r = 0; r < static_cast<std::size_t>(stencil.count); ++r)
      for (std::size_t c = 0; c <= r; ++c)
        part.add(stencil.node[r], stencil.node[c], scale * stencil.weight[r] * stencil.weight[c] * d);
  });
}

void HingeFriction::bound_stiffness(const Model& model, StiffnessBound& bound) const {
  for (const Hinge& h : model.fabric.hinges()) {
    const HingeStencil stencil = hinge_stencil(h);
    double sum = 0.0;
    for (int k = 0; k < stencil.count; ++k) sum += std::abs(stencil.weight[static_cast<std::size_t>(k)]);
    // D's rows sum to at most 1/ε in absolute value inside the rounding, and past it those of the
    // projection (I − k̂·k̂ᵀ)/|k| to at most (1 + √3)/2 / |k|, |k| ≥ ε.
    const double row_sum = 0.5 * (1.0 + std::sqrt(3.0)) / rounding_angle_of(model, h);
    const double scale = 0.5 * friction_moment_of(model, h) * side_length(model, h) * row_sum;
    for (int k = 0; k < stencil.count; ++k)
      bound.per_node[static_cast<std::size_t>(stencil.node[static_cast<std::size_t>(k)])] +=
          scale * std::abs(stencil.weight[static_cast<std::size_t>(k)]) * sum;
  }
}

}  // namespace fabform
