// The two-sided Cholesky: the split it makes, its solve against CHOLMOD's on the whole matrix,
// and a matrix that fails to be positive definite on either side or only in the separator's
// complement.
#include "linalg/substructured_cholesky.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/grid_stiffness.hpp"

namespace fabform::substructured_cholesky_test {
namespace {

Eigen::VectorXd ramp(Eigen::Index n) {
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = std::cos(0.11 * static_cast<double>(i)) - 0.2;
  return b;
}

// 30 × 30 nodes: 2700 unknowns, split with a lower minimum than Newton's 300 000.
constexpr int kSide = 30;
constexpr int kMinimum = 2000;

TEST(SubstructuredCholesky, SmallMatricesAreNotSplit) {
  EXPECT_EQ(SubstructuredCholesky::split(test::to_lower_csc(test::grid_stiffness(20, 0.05)), kMinimum), nullptr);
  EXPECT_EQ(SubstructuredCholesky::split(test::to_lower_csc(test::grid_stiffness(kSide, 0.05))), nullptr);
}

// A graph without edges: whatever METIS puts in the separator, each piece is solved alone.
TEST(SubstructuredCholesky, DiagonalMatrixSolvesExactly) {
  Eigen::SparseMatrix<double> diagonal(3000, 3000);
  diagonal.setIdentity();
  diagonal *= 4.0;
  const LowerCsc m = test::to_lower_csc(diagonal);
  const auto split = SubstructuredCholesky::split(m, kMinimum);
  if (!split) GTEST_SKIP() << "METIS left no separator, so the matrix is factorised whole";
  ASSERT_TRUE(split->factorize(m));
  EXPECT_TRUE(split->solve(ramp(m.n)) == ramp(m.n) / 4.0);  // quarters are exact
}

TEST(SubstructuredCholesky, SolvesAsTheWholeFactorisationDoes) {
  for (double shift : {1.0, 1e-3, 1e-6}) {
    const LowerCsc m = test::to_lower_csc(test::grid_stiffness(kSide, shift));
    const auto split = SubstructuredCholesky::split(m, kMinimum);
    ASSERT_NE(split, nullptr);
    EXPECT_GT(static_cast<int>(split->separator().size()), 0);
    EXPECT_LE(static_cast<int>(split->separator().size()), 2 * kSide * 3);
    ASSERT_TRUE(split->factorize(m));
    CholmodFactor whole;
    whole.analyse(m);
    ASSERT_TRUE(whole.factorize(m));
    Eigen::VectorXd expected = ramp(m.n);
    whole.solve(&expected);
    const Eigen::VectorXd x = split->solve(ramp(m.n));
    // Both are backward stable: they differ by rounding amplified by the condition number,
    // about 10 / shift here; 1e-13 of it (a few hundred ulps per unit condition) bounds it.
    EXPECT_LE((x - expected).norm(), 1e-13 * (10.0 / shift) * expected.norm()) << "shift " << shift;
  }
}

TEST(SubstructuredCholesky, RefactorisesNewValuesOnTheSamePattern) {
  const LowerCsc first = test::to_lower_csc(test::grid_stiffness(kSide, 0.1, 1));
  const LowerCsc second = test::to_lower_csc(test::grid_stiffness(kSide, 0.1, 2));
  const auto split = SubstructuredCholesky::split(first, kMinimum);
  ASSERT_NE(split, nullptr);
  ASSERT_TRUE(split->factorize(first));
  ASSERT_TRUE(split->factorize(second));
  const Eigen::VectorXd x = split->solve(ramp(second.n));
  const Eigen::SparseMatrix<double> a = test::symmetric(test::grid_stiffness(kSide, 0.1, 2));
  EXPECT_LE((a * x - ramp(second.n)).norm(), 1e-10 * ramp(second.n).norm());
}

// A negative diagonal entry anywhere, in a side (the grid's corners are in one or the other) or
// in the separator, makes it fail.
TEST(SubstructuredCholesky, ReportsAMatrixThatIsNotPositiveDefinite) {
  const Eigen::SparseMatrix<double> good = test::grid_stiffness(kSide, 0.05);
  const auto split = SubstructuredCholesky::split(test::to_lower_csc(good), kMinimum);
  ASSERT_NE(split, nullptr);
  for (int u : {0, 3 * kSide * kSide - 1, split->separator().front(), split->separator().back()}) {
    Eigen::SparseMatrix<double> bad = good;
    bad.coeffRef(u, u) = -1.0;
    EXPECT_FALSE(split->factorize(test::to_lower_csc(bad))) << "unknown " << u;
  }
  EXPECT_TRUE(split->factorize(test::to_lower_csc(good)));
}

}  // namespace
}  // namespace fabform::substructured_cholesky_test
