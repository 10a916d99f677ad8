// Block Gauss–Seidel against what a smoother must be: a node alone is solved exactly by one
// sweep; a forward sweep and a backward one, from zero, are a symmetric operator; sweeps
// converge to the direct solution (Eigen's LDLT) of a positive definite grid stiffness; a node
// with no stiffness takes no move.
#include "linalg/block_gauss_seidel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SparseCholesky>

#include "support/grid_stiffness.hpp"

namespace fabform {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

std::vector<int> nodes_of_three(Eigen::Index unknowns) {
  std::vector<int> start;
  for (Eigen::Index u = 0; u <= unknowns; u += 3) start.push_back(static_cast<int>(u));
  return start;
}

Eigen::VectorXd load(Eigen::Index n) {
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = std::cos(0.7 * static_cast<double>(i));
  return b;
}

// x after a forward sweep and a backward one from zero: the smoother as an operator on b.
Eigen::VectorXd symmetric_sweep(const BlockGaussSeidel& s, const RowMatrix& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  s.sweep(a, b, x, true);
  s.sweep(a, b, x, false);
  return x;
}

TEST(BlockGaussSeidel, SolvesANodeAloneInOneSweep) {
  const RowMatrix a = test::symmetric(test::grid_stiffness(1, 0.3));
  const BlockGaussSeidel s(a, {0, 3});
  const Eigen::VectorXd b = load(3);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
  s.sweep(a, b, x, true);
  const Eigen::Vector3d exact = Eigen::Matrix3d(Eigen::MatrixXd(a)).inverse() * b;
  EXPECT_LE((x - exact).norm(), 1e-12 * exact.norm());
}

TEST(BlockGaussSeidel, AForwardAndABackwardSweepAreSymmetric) {
  const RowMatrix a = test::symmetric(test::grid_stiffness(9, 0.01));
  const BlockGaussSeidel s(a, nodes_of_three(a.rows()));
  Eigen::VectorXd u = load(a.rows()), v = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  const double uv = u.dot(symmetric_sweep(s, a, v)), vu = v.dot(symmetric_sweep(s, a, u));
  EXPECT_NEAR(uv, vu, 1e-12 * (std::abs(uv) + std::abs(vu)));
  EXPECT_GT(u.dot(symmetric_sweep(s, a, u)), 0.0);
}

TEST(BlockGaussSeidel, SweepsConvergeToTheDirectSolution) {
  const Eigen::SparseMatrix<double> lower = test::grid_stiffness(6, 0.5);
  const RowMatrix a = test::symmetric(lower);
  const BlockGaussSeidel s(a, nodes_of_three(a.rows()));
  const Eigen::VectorXd b = load(a.rows());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> direct(lower);
  const Eigen::VectorXd exact = direct.solve(b);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  for (int k = 0; k < 200; ++k) s.sweep(a, b, x, k % 2 == 0);
  // Each symmetric pair of sweeps shrinks the energy-norm error; 200 sweeps on this well-shifted
  // grid reach rounding.
  EXPECT_LE((x - exact).norm(), 1e-9 * exact.norm());
}

TEST(BlockGaussSeidel, GivesANodeWithNoStiffnessNoMove) {
  RowMatrix a = test::symmetric(test::grid_stiffness(3, 0.1));
  a.prune([](Eigen::Index row, Eigen::Index column, double) { return row >= 3 && column >= 3; });  // node 0: empty
  const BlockGaussSeidel s(a, nodes_of_three(a.rows()));
  Eigen::VectorXd x = Eigen::VectorXd::Constant(a.rows(), 0.25);
  s.sweep(a, load(a.rows()), x, true);
  EXPECT_TRUE(x.head<3>().isZero(0.0));
  EXPECT_TRUE(x.allFinite());
}

TEST(BlockGaussSeidel, RefusesBlocksThatDoNotFit) {
  const RowMatrix a = test::symmetric(test::grid_stiffness(2, 0.1));
  EXPECT_THROW(BlockGaussSeidel(a, {0, 3, 6, 9}), std::invalid_argument);    // 12 unknowns
  EXPECT_THROW(BlockGaussSeidel(a, {0, 4, 8, 12}), std::invalid_argument);   // 4 a node
  EXPECT_THROW(BlockGaussSeidel(a, {0, 6, 3, 12}), std::invalid_argument);   // backwards
}

}  // namespace
}  // namespace fabform
