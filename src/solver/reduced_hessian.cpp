#include "solver/reduced_hessian.hpp"

#include <cstddef>

#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/spring_energy.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Block (row node, column node) of the reduced matrix; on the diagonal only its lower half.
void add_block(const FreeDirections& d, int row, int col, const Eigen::Matrix3d& stiffness,
               Triplets* out) {
  const Eigen::Matrix3d block = d.of(row).transpose() * stiffness * d.of(col);
  const int r0 = d.offset[static_cast<std::size_t>(row)];
  const int c0 = d.offset[static_cast<std::size_t>(col)];
  for (int r = 0; r < d.count(row); ++r)
    for (int c = 0; c < d.count(col); ++c)
      if (r0 + r >= c0 + c) out->emplace_back(r0 + r, c0 + c, block(r, c));
}

// A spring between a and b adds [[K, −K], [−K, K]]; the coupling block goes below the diagonal.
void add_spring(const FreeDirections& d, int a, int b, const Eigen::Matrix3d& k, Triplets* out) {
  add_block(d, a, a, k, out);
  add_block(d, b, b, k, out);
  const bool b_below = d.offset[static_cast<std::size_t>(b)] > d.offset[static_cast<std::size_t>(a)];
  if (b_below) add_block(d, b, a, -k, out);
  else add_block(d, a, b, -k, out);
}

// A hinge adds its Hessian 2·B·s·(c_a·c_b)·I over each pair of the nodes it reaches: exact,
// constant and positive semi-definite (hinge_bending.hpp); each pair once, below the diagonal.
void add_hinge(const FreeDirections& d, const HingeStencil& stencil, double scale, Triplets* out) {
  for (int r = 0; r < stencil.count; ++r)
    for (int c = 0; c <= r; ++c) {
      const int a = stencil.node[static_cast<std::size_t>(r)], b = stencil.node[static_cast<std::size_t>(c)];
      const Eigen::Matrix3d k = scale * stencil.weight[static_cast<std::size_t>(r)] *
                                stencil.weight[static_cast<std::size_t>(c)] * Eigen::Matrix3d::Identity();
      if (r == c) add_block(d, a, a, k, out);
      else if (d.offset[static_cast<std::size_t>(a)] > d.offset[static_cast<std::size_t>(b)]) add_block(d, a, b, k, out);
      else add_block(d, b, a, k, out);
    }
}

}  // namespace

Eigen::SparseMatrix<double> reduced_hessian(const Model& model,
                                            const std::vector<Eigen::Vector3d>& x,
                                            const FreeDirections& directions) {
  Triplets triplets;
  triplets.reserve(model.fabric.springs().size() * 21 + static_cast<std::size_t>(directions.unknowns()));
  for (int u = 0; u < directions.unknowns(); ++u) triplets.emplace_back(u, u, 0.0);
  const std::vector<Spring>& springs = model.fabric.springs();
  std::vector<Eigen::Matrix3d> stiffness(springs.size());
#pragma omp parallel for schedule(static) if (springs.size() >= kMinParallelItems)
  for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(springs.size()); ++i) {
    const Spring& s = springs[static_cast<std::size_t>(i)];
    stiffness[static_cast<std::size_t>(i)] = projected_spring_stiffness(
        x[static_cast<std::size_t>(s.a)], x[static_cast<std::size_t>(s.b)], s, model.table(s.kind));
  }
  for (std::size_t i = 0; i < springs.size(); ++i)
    add_spring(directions, springs[i].a, springs[i].b, stiffness[i], &triplets);
  if (model.bending_rigidity_Nm)
    for (const Hinge& h : model.fabric.hinges())
      add_hinge(directions, hinge_stencil(h), 2.0 * *model.bending_rigidity_Nm * h.shape_factor, &triplets);
  Eigen::SparseMatrix<double> hessian(directions.unknowns(), directions.unknowns());
  hessian.setFromTriplets(triplets.begin(), triplets.end());
  return hessian;
}

}  // namespace fabform
