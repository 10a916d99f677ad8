#include "solver/reduced_hessian.hpp"

#include <cstddef>

namespace fabform {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Gathers the terms' blocks into the lower triangle of the reduced matrix.
class ReducedAssembly final : public StiffnessSink {
 public:
  ReducedAssembly(const FreeDirections& directions, Triplets* out) : d_(directions), out_(out) {}

  void add(int row, int col, const Eigen::Matrix3d& stiffness) override {
    if (row == col || offset(row) > offset(col)) add_block(row, col, stiffness);
    else add_block(col, row, stiffness.transpose());
  }

 private:
  int offset(int node) const { return d_.offset[static_cast<std::size_t>(node)]; }

  // Block (row node, column node) of the reduced matrix; on the diagonal only its lower half.
  void add_block(int row, int col, const Eigen::Matrix3d& stiffness) {
    const Eigen::Matrix3d block = d_.of(row).transpose() * stiffness * d_.of(col);
    const int r0 = offset(row), c0 = offset(col);
    for (int r = 0; r < d_.count(row); ++r)
      for (int c = 0; c < d_.count(col); ++c)
        if (r0 + r >= c0 + c) out_->emplace_back(r0 + r, c0 + c, block(r, c));
  }

  const FreeDirections& d_;
  Triplets* out_;
};

}  // namespace

Eigen::SparseMatrix<double> reduced_hessian(const Model& model,
                                            const std::vector<Eigen::Vector3d>& x,
                                            const FreeDirections& directions, const Term* lagged) {
  Triplets triplets;
  triplets.reserve(model.fabric.springs().size() * 21 + static_cast<std::size_t>(directions.unknowns()));
  for (int u = 0; u < directions.unknowns(); ++u) triplets.emplace_back(u, u, 0.0);
  ReducedAssembly assembly(directions, &triplets);
  for (const auto& term : model.terms) term->add_stiffness(model, x, assembly);
  if (lagged) lagged->add_stiffness(model, x, assembly);
  Eigen::SparseMatrix<double> hessian(directions.unknowns(), directions.unknowns());
  hessian.setFromTriplets(triplets.begin(), triplets.end());
  return hessian;
}

}  // namespace fabform
