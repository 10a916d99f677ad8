#include "fabform/model/hinge_bending.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>

#include "fabform/model/model.hpp"

namespace fabform {

Eigen::Vector3d bend_vector(const Hinge& hinge, const std::vector<Eigen::Vector3d>& x, int moved,
                            const Eigen::Vector3d& at) {
  const auto p = [&](int node) -> const Eigen::Vector3d& { return node == moved ? at : x[static_cast<std::size_t>(node)]; };
  Eigen::Vector3d k = hinge.weight[0] * p(hinge.edge[0]) + hinge.weight[1] * p(hinge.edge[1]);
  for (std::size_t w = 0; w < 2; ++w) k += 0.5 * hinge.weight[2 + w] * (p(hinge.wing[w][0]) + p(hinge.wing[w][1]));
  return k;
}

double hinge_energy(const Hinge& hinge, double rigidity_Nm, const std::vector<Eigen::Vector3d>& x, int moved,
                    const Eigen::Vector3d& at) {
  return rigidity_Nm * hinge.shape_factor * bend_vector(hinge, x, moved, at).squaredNorm();
}

HingeStencil hinge_stencil(const Hinge& hinge) {
  HingeStencil out;
  const auto add = [&](int node, double c) {
    for (int k = 0; k < out.count; ++k)
      if (out.node[static_cast<std::size_t>(k)] == node) {
        out.weight[static_cast<std::size_t>(k)] += c;
        return;
      }
    out.node[static_cast<std::size_t>(out.count)] = node;
    out.weight[static_cast<std::size_t>(out.count)] = c;
    ++out.count;
  };
  add(hinge.edge[0], hinge.weight[0]);
  add(hinge.edge[1], hinge.weight[1]);
  for (std::size_t w = 0; w < 2; ++w)
    for (const int node : hinge.wing[w]) add(node, 0.5 * hinge.weight[2 + w]);
  return out;
}

std::size_t stencil_index(const HingeStencil& stencil, int node) {
  for (int k = 0; k < stencil.count; ++k)
    if (stencil.node[static_cast<std::size_t>(k)] == node) return static_cast<std::size_t>(k);
  throw std::logic_error("a hinge listed at a node does not reach it");
}

Eigen::Vector3d flat_side(const Model& model, const Hinge& hinge) {
  return model.fabric.rest_position(hinge.edge[1]) - model.fabric.rest_position(hinge.edge[0]);
}

double along_bending_direction(const Model& model, const Hinge& hinge, double value_warp, double value_weft) {
  if (value_warp == value_weft) return value_warp;
  const Eigen::Vector2d e = flat_side(model, hinge).head<2>();
  return (value_warp * e.y() * e.y() + value_weft * e.x() * e.x()) / e.squaredNorm();
}

double HingeBending::rigidity_of(const Model& model, const Hinge& hinge) const {
  return along_bending_direction(model, hinge, rigidity_warp_Nm_, rigidity_weft_Nm_);
}

std::string HingeBending::describe(const Model& model) const {
  char text[240];
  if (rigidity_warp_Nm_ == rigidity_weft_Nm_)
    std::snprintf(text, sizeof text,
                  "bending: hinges across %zu face sides (quadratic bending of a flat fabric), flexural rigidity %.6g N·m",
                  model.fabric.hinges().size(), rigidity_warp_Nm_);
  else
    std::snprintf(text, sizeof text,
                  "bending: hinges across %zu face sides (quadratic bending of a flat fabric), flexural rigidity "
                  "%.6g N·m along the warp, %.6g N·m along the weft",
                  model.fabric.hinges().size(), rigidity_warp_Nm_, rigidity_weft_Nm_);
  return text;
}

double HingeBending::energy(const Model& model, const Positions& x) const {
  double energy = 0.0;
  for (const Hinge& h : model.fabric.hinges()) energy += hinge_energy(h, rigidity_of(model, h), x);
  return energy;
}

Eigen::Vector3d HingeBending::force_at(const Model& model, const Positions& x, int node,
                                       const Eigen::Vector3d& at) const {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const int i : model.fabric.hinges_at(node)) {
    const Hinge& h = model.fabric.hinges()[static_cast<std::size_t>(i)];
    const HingeStencil stencil = hinge_stencil(h);
    force -= 2.0 * rigidity_of(model, h) * h.shape_factor * stencil.weight[stencil_index(stencil, node)] *
             bend_vector(h, x, node, at);
  }
  return force;
}

double HingeBending::node_energy(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const {
  double energy = 0.0;
  for (const int i : model.fabric.hinges_at(node)) {
    const Hinge& h = model.fabric.hinges()[static_cast<std::size_t>(i)];
    energy += hinge_energy(h, rigidity_of(model, h), x, node, at);
  }
  return energy;
}

double HingeBending::node_energy_change(const Model& model, const Positions& x, int node,
                                        const Eigen::Vector3d& at) const {
  return node_energy(model, x, node, at) - node_energy(model, x, node, x[static_cast<std::size_t>(node)]);
}

void HingeBending::add_stiffness(const Model& model, const Positions& /*x*/, StiffnessSink& sink) const {
  const std::vector<Hinge>& hinges = model.fabric.hinges();
  sink.add_each(hinges.size(), [&](std::size_t k, StiffnessSink& part) {
    const Hinge& h = hinges[k];
    const HingeStencil stencil = hinge_stencil(h);
    const double scale = 2.0 * rigidity_of(model, h) * h.shape_factor;
    for (std::size_t r = 0; r < static_cast<std::size_t>(stencil.count); ++r)
      for (std::size_t c = 0; c <= r; ++c)
        part.add(stencil.node[r], stencil.node[c],
                 scale * stencil.weight[r] * stencil.weight[c] * Eigen::Matrix3d::Identity());
  });
}

void HingeBending::bound_stiffness(const Model& model, StiffnessBound& bound) const {
  for (const Hinge& h : model.fabric.hinges()) {
    const HingeStencil stencil = hinge_stencil(h);
    double sum = 0.0;
    for (int k = 0; k < stencil.count; ++k) sum += std::abs(stencil.weight[static_cast<std::size_t>(k)]);
    for (int k = 0; k < stencil.count; ++k)
      bound.per_node[static_cast<std::size_t>(stencil.node[static_cast<std::size_t>(k)])] +=
          rigidity_of(model, h) * h.shape_factor * std::abs(stencil.weight[static_cast<std::size_t>(k)]) * sum;
  }
}

}  // namespace fabform
