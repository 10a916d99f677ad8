#include "fabform/model/hinge_bending.hpp"

#include <algorithm>
#include <cstddef>

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

double bending_energy(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  if (!model.bending_rigidity_Nm) return 0.0;
  double energy = 0.0;
  for (const Hinge& h : model.fabric.hinges()) energy += hinge_energy(h, *model.bending_rigidity_Nm, x);
  return energy;
}

Eigen::Vector3d bending_force_at(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                                 const Eigen::Vector3d& at) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  if (!model.bending_rigidity_Nm) return force;
  for (const int i : model.fabric.hinges_at(node)) {
    const Hinge& h = model.fabric.hinges()[static_cast<std::size_t>(i)];
    const HingeStencil stencil = hinge_stencil(h);
    const auto k = static_cast<std::size_t>(
        std::find(stencil.node.begin(), stencil.node.begin() + stencil.count, node) - stencil.node.begin());
    force -= 2.0 * *model.bending_rigidity_Nm * h.shape_factor * stencil.weight[k] * bend_vector(h, x, node, at);
  }
  return force;
}

double node_bending_energy(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                           const Eigen::Vector3d& at) {
  if (!model.bending_rigidity_Nm) return 0.0;
  double energy = 0.0;
  for (const int i : model.fabric.hinges_at(node))
    energy += hinge_energy(model.fabric.hinges()[static_cast<std::size_t>(i)], *model.bending_rigidity_Nm, x, node, at);
  return energy;
}

}  // namespace fabform
