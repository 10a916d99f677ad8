#include "solver/free_directions.hpp"

#include <optional>
#include <vector>

#include "fabform/thread_count.hpp"

namespace fabform {
namespace {

// Gram–Schmidt over the free axes with the free part of the normal removed first (and on a
// crease its second face's normal, so that only the crease's direction stays). The kept
// directions span the free axes' plane within the tangent plane; a projected axis shorter than
// 1e-3 is (to rounding) a combination of those already kept and is dropped.
int node_basis(AxisMask locks, const NodeContact& contact, Eigen::Matrix3d* basis) {
  Eigen::Vector3d normal = contact.active() ? remove_locked(contact.normal, locks)
                                            : Eigen::Vector3d::Zero();
  if (normal.squaredNorm() > 0.0) normal.normalize();
  Eigen::Vector3d second = contact.active() && locks == 0 ? contact.crease : Eigen::Vector3d::Zero();
  second -= second.dot(normal) * normal;
  if (second.squaredNorm() > 0.0) second.normalize();
  basis->setZero();
  int count = 0;
  for (int axis = 0; axis < 3; ++axis) {
    if (locks & (1 << axis)) continue;
    Eigen::Vector3d v = Eigen::Vector3d::Unit(axis);
    v -= v.dot(normal) * normal;
    v -= v.dot(second) * second;
    for (int c = 0; c < count; ++c) v -= v.dot(basis->col(c)) * basis->col(c);
    if (v.norm() > 1e-3) basis->col(count++) = v.normalized();
  }
  return count;
}

int free_axes(AxisMask locks) {
  int count = 0;
  for (int axis = 0; axis < 3; ++axis) count += (locks & (1 << axis)) ? 0 : 1;
  return count;
}

}  // namespace

FreeDirections free_directions(const Model& model, const std::vector<NodeContact>& contact) {
  const auto n = static_cast<std::size_t>(model.node_count());
  FreeDirections d{std::vector<int>(n + 1, 0), std::vector<Eigen::Matrix3d>(n)};
  std::vector<int> used(n);
#pragma omp parallel for schedule(static) if (n >= static_cast<std::size_t>(kMinParallelItems))
  for (std::size_t k = 0; k < n; ++k) {
    used[k] = node_basis(model.locks[k], contact[k], &d.basis[k]);
    d.offset[k + 1] = free_axes(model.locks[k]);
  }
  for (std::size_t k = 0; k < n; ++k) {
    d.used += used[k];
    d.offset[k + 1] += d.offset[k];
  }
  return d;
}

std::vector<Eigen::Vector3d> node_steps(const FreeDirections& directions,
                                        const Eigen::VectorXd& unknowns) {
  std::vector<Eigen::Vector3d> steps(directions.basis.size());
#pragma omp parallel for schedule(static) if (steps.size() >= static_cast<std::size_t>(kMinParallelItems))
  for (std::size_t k = 0; k < steps.size(); ++k) {
    Eigen::Vector3d local = Eigen::Vector3d::Zero();
    const int node = static_cast<int>(k);
    for (int c = 0; c < directions.count(node); ++c) local[c] = unknowns[directions.offset[k] + c];
    steps[k] = directions.of(node) * local;
  }
  return steps;
}

Eigen::VectorXd reduced_forces(const FreeDirections& directions,
                               const std::vector<Eigen::Vector3d>& forces) {
  Eigen::VectorXd reduced(directions.unknowns());
#pragma omp parallel for schedule(static) if (forces.size() >= static_cast<std::size_t>(kMinParallelItems))
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const int node = static_cast<int>(k);
    const Eigen::Vector3d local = directions.of(node).transpose() * forces[k];
    for (int c = 0; c < directions.count(node); ++c) reduced[directions.offset[k] + c] = local[c];
  }
  return reduced;
}

namespace {

// A garment's panels share the lattice's indices side by side, but their seams join nodes the
// lattice's lines and coarse grids know nothing of: they are solved as a general mesh.
std::optional<LatticeUnknowns> lattice_unknowns(const FreeDirections& directions, const Fabric& fabric) {
  if (fabric.spec().mesh == FabricSpec::Mesh::arc || fabric.spec().shape == FabricSpec::Shape::panels ||
      fabric.nodes_warp() < 2 || fabric.nodes_weft() < 2)
    return std::nullopt;
  LatticeUnknowns l;
  l.lattice_size = {fabric.nodes_warp(), fabric.nodes_weft()};
  l.node_lattice.resize(static_cast<std::size_t>(fabric.node_count()));
  l.node.resize(static_cast<std::size_t>(directions.unknowns()));
  l.direction.resize(l.node.size());
#pragma omp parallel for schedule(static) if (fabric.node_count() >= kMinParallelItems)
  for (int k = 0; k < fabric.node_count(); ++k) {
    l.node_lattice[static_cast<std::size_t>(k)] = {fabric.i_of(k), fabric.j_of(k)};
    for (int c = 0; c < directions.count(k); ++c) {
      const auto u = static_cast<std::size_t>(directions.offset[k] + c);
      l.node[u] = k;
      l.direction[u] = directions.of(k).col(c);
    }
  }
  return l;
}

}  // namespace

UnknownLayout unknown_layout(const FreeDirections& directions, const Fabric& fabric) {
  UnknownLayout layout;
  layout.component.resize(static_cast<std::size_t>(directions.unknowns()));
  const int nodes = static_cast<int>(directions.offset.size()) - 1;
#pragma omp parallel for schedule(static) if (nodes >= kMinParallelItems)
  for (int k = 0; k < nodes; ++k)
    for (int c = 0; c < directions.count(k); ++c) layout.component[directions.offset[k] + c] = c;
  layout.lattice = lattice_unknowns(directions, fabric);
  return layout;
}

}  // namespace fabform
