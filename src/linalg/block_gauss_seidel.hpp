#pragma once
// Block Gauss–Seidel, the lattice multigrid's smoother: each node's unknowns are solved together,
// which a membrane needs, as its in-plane stiffness couples a node's x, y and z (on a curved
// fabric) a thousand times more strongly than the tension holds the normal. The nodes are taken
// in lattice order, one after another: a sweep in colours (the nodes of a colour at once, on
// every thread) took 2031 conjugate-gradient iterations against 192 on the dome at N = 401, as
// it no longer carries a correction along a line of taut springs through a slack region in one
// sweep. A forward sweep followed by a backward one is a symmetric smoother.
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace fabform {

class BlockGaussSeidel {
 public:
  BlockGaussSeidel() = default;
  /// `a` whole and symmetric; `block_start` each node's first unknown (its unknowns are
  /// consecutive, at most 3), and one past the last.
  BlockGaussSeidel(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, std::vector<int> block_start);

  /// One sweep on a x = b, updating x.
  void sweep(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             bool forward) const;

 private:
  void relax(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             int block) const;

  std::vector<int> block_start_;
  std::vector<Eigen::Matrix3d> inverse_;  // per node: its diagonal block's (pseudo-)inverse, padded
};

}  // namespace fabform
