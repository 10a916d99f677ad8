// hypre's BoomerAMG-preconditioned conjugate gradients against a direct solve (Eigen's LDLT) of
// the same grid stiffness: the tolerance it claims is the residual it leaves, a tight tolerance
// gives the direct answer, a loose one still a descent direction, and its cost in iterations
// does not grow with the grid (multigrid's promise, checked on a 10× larger grid).
#include "linalg/amg_conjugate_gradient.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "support/grid_stiffness.hpp"

namespace fabform::amg_conjugate_gradient_test {
namespace {

using test::xyz_components;

Eigen::VectorXd load(Eigen::Index n) {
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = 1.0 / (1.0 + static_cast<double>(i % 17));
  return b;
}

TEST(AmgConjugateGradient, LeavesTheResidualItClaims) {
  const Eigen::SparseMatrix<double> lower = test::grid_stiffness(30, 0.01);
  const Eigen::SparseMatrix<double> a = test::symmetric(lower);
  AmgConjugateGradient cg;
  cg.set_matrix(lower, xyz_components(lower.rows()));
  const Eigen::VectorXd b = load(lower.rows());
  for (double tolerance : {1e-2, 1e-6}) {
    const CgResult r = cg.solve(b, tolerance, 500);
    const double residual = (b - a * r.x).norm() / b.norm();
    EXPECT_LE(residual, tolerance) << tolerance;
    // hypre's own figure is the recomputed one, to rounding of the norms.
    EXPECT_NEAR(r.relative_residual, residual, 1e-9 + 1e-6 * residual) << tolerance;
    EXPECT_GT(r.iterations, 0);
  }
}

TEST(AmgConjugateGradient, ATightToleranceGivesTheDirectAnswer) {
  const Eigen::SparseMatrix<double> lower = test::grid_stiffness(20, 0.01, 3);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> direct(lower);
  ASSERT_EQ(direct.info(), Eigen::Success);
  const Eigen::VectorXd b = load(lower.rows());
  const Eigen::VectorXd exact = direct.solve(b);
  AmgConjugateGradient cg;
  cg.set_matrix(lower, xyz_components(lower.rows()));
  const CgResult r = cg.solve(b, 1e-12, 1000);
  // The error is at most the condition number (≲ 1e4 with this shift) times the residual.
  EXPECT_LE((r.x - exact).lpNorm<Eigen::Infinity>(), 1e-7 * exact.lpNorm<Eigen::Infinity>());
}

TEST(AmgConjugateGradient, AnyIterateIsADescentDirection) {
  const Eigen::SparseMatrix<double> lower = test::grid_stiffness(25, 1e-4, 5);
  AmgConjugateGradient cg;
  cg.set_matrix(lower, xyz_components(lower.rows()));
  const Eigen::VectorXd b = load(lower.rows());
  for (int cap : {1, 2, 5}) {
    const CgResult r = cg.solve(b, 1e-14, cap);
    EXPECT_LE(r.iterations, cap);
    EXPECT_GT(r.x.dot(b), 0.0) << cap;
    EXPECT_TRUE(r.x.allFinite());
  }
}

TEST(AmgConjugateGradient, IterationsDoNotGrowWithTheGrid) {
  const auto iterations = [](int side) {
    const Eigen::SparseMatrix<double> lower = test::grid_stiffness(side, 0.01);
    AmgConjugateGradient cg;
    cg.set_matrix(lower, xyz_components(lower.rows()));
    return cg.solve(load(lower.rows()), 1e-8, 1000).iterations;
  };
  const int small = iterations(20), large = iterations(64);  // 1 200 and 12 288 unknowns
  EXPECT_LE(large, small + small / 2 + 2) << small << " on 20 × 20, " << large << " on 64 × 64";
}

TEST(AmgConjugateGradient, ZeroLoadIsZeroStep) {
  const Eigen::SparseMatrix<double> lower = test::grid_stiffness(8, 0.01);
  AmgConjugateGradient cg;
  cg.set_matrix(lower, xyz_components(lower.rows()));
  const CgResult r = cg.solve(Eigen::VectorXd::Zero(lower.rows()), 1e-8, 100);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_TRUE(r.x.isZero(0.0));
}

TEST(AmgConjugateGradient, RefusesMisuse) {
  const Eigen::SparseMatrix<double> lower = test::grid_stiffness(4, 0.01);
  AmgConjugateGradient cg;
  EXPECT_THROW(cg.solve(load(lower.rows()), 1e-8, 10), std::logic_error);
  EXPECT_THROW(cg.set_matrix(lower, {0, 1, 2}), std::invalid_argument);
  cg.set_matrix(lower, xyz_components(lower.rows()));
  EXPECT_THROW(cg.solve(load(lower.rows() - 1), 1e-8, 10), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::amg_conjugate_gradient_test
