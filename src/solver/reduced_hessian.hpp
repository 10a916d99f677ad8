#pragma once
// Newton's matrix: the sum of the model's terms' stiffness (term.hpp), each positive
// semi-definite, in the nodes' free directions (free_directions.hpp).
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fabform/model/model.hpp"
#include "solver/free_directions.hpp"

namespace fabform {

/// Assembles Newton's matrix, lower triangle only (what the factorisations read), every diagonal
/// entry stored so that a regularisation can be added to it in place. The terms' 3 × 3 blocks,
/// in the free directions, are summed per pair of nodes into the pairs the last assembly found,
/// then written out column by column: no list of entries to sort. The pairs are found again, in
/// a second pass of the terms, only when a term couples two nodes they lack (the first time),
/// and are never dropped, so the matrix's pattern stays the same from one Newton step to the next.
class ReducedHessian {
 public:
  /// `lagged` is a term Newton holds for one iteration (friction), added to the model's own.
  /// `slack_share`: what a slack spring keeps of its table's steepest slope along it
  /// (StiffnessSink::slack_share); 0 assembles ∂²Π/∂x² itself, projected.
  Eigen::SparseMatrix<double> assemble(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                       const FreeDirections& directions, const Term* lagged = nullptr,
                                       double slack_share = 0.0);

 private:
  bool sum_blocks(const Model& model, const std::vector<Eigen::Vector3d>& x, const FreeDirections& directions,
                  const Term* lagged, double slack_share);
  void add_pairs(int nodes, std::vector<std::pair<int, int>> missing);
  int column_entries(const FreeDirections& directions, int j) const;
  Eigen::SparseMatrix<double> written_out(const FreeDirections& directions) const;

  std::vector<int> start_{0};          // per column node j, its first pair; one more at the end
  std::vector<int> row_;               // per pair (i, j), i ≥ j: i, ascending within a column
  std::vector<Eigen::Matrix3d> block_;  // per pair: the terms' blocks (row i, column j), summed
};

/// One assembly, with no pairs kept.
Eigen::SparseMatrix<double> reduced_hessian(const Model& model,
                                            const std::vector<Eigen::Vector3d>& x,
                                            const FreeDirections& directions,
                                            const Term* lagged = nullptr);

}  // namespace fabform
