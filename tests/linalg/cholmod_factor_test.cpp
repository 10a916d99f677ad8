// The CHOLMOD wrapper: its solve against a dense factorisation, its four solve steps against
// its solve, the trailing block against a dense factor, and the bisection's separator.
#include "linalg/cholmod_factor.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include "support/grid_stiffness.hpp"

namespace fabform::cholmod_factor_test {
namespace {

Eigen::VectorXd ramp(Eigen::Index n) {
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.1;
  return b;
}

TEST(CholmodFactor, SolvesAsADenseFactorisationDoes) {
  const Eigen::SparseMatrix<double> lower = test::grid_stiffness(8, 0.05);
  const LowerCsc m = test::to_lower_csc(lower);
  CholmodFactor f;
  f.analyse(m);
  ASSERT_TRUE(f.factorize(m));
  Eigen::VectorXd x = ramp(m.n);
  f.solve(&x);
  const Eigen::MatrixXd dense(test::symmetric(lower));
  const Eigen::VectorXd expected = dense.llt().solve(ramp(m.n));
  // Both are backward stable; the matrix's condition (shift 0.05 against blocks of order 1,
  // about 1e3) bounds their difference far below 1e-9.
  EXPECT_LE((x - expected).norm(), 1e-9 * expected.norm());
}

TEST(CholmodFactor, StepsComposeToTheSolve) {
  const LowerCsc m = test::to_lower_csc(test::grid_stiffness(8, 0.05));
  CholmodFactor f;
  f.analyse(m);
  ASSERT_TRUE(f.factorize(m));
  Eigen::VectorXd whole = ramp(m.n), steps = ramp(m.n);
  f.solve(&whole);
  for (auto step : {CholmodFactor::Step::permute, CholmodFactor::Step::forward,
                    CholmodFactor::Step::backward, CholmodFactor::Step::unpermute})
    f.apply(step, &steps);
  EXPECT_LE((whole - steps).norm(), 1e-12 * whole.norm());
}

TEST(CholmodFactor, ReportsAMatrixThatIsNotPositiveDefinite) {
  Eigen::SparseMatrix<double> lower = test::grid_stiffness(8, 0.05);
  lower.coeffRef(40, 40) = -1.0;
  const LowerCsc m = test::to_lower_csc(lower);
  CholmodFactor f;
  f.analyse(m);
  EXPECT_FALSE(f.factorize(m));
}

// A dense matrix has a chain for its elimination tree, so a given order stays as given and the
// factor's trailing block is the dense factor's.
TEST(CholmodFactor, TrailingBlockIsTheDenseFactorsCorner) {
  const int n = 12, tail = 5;
  Eigen::MatrixXd g = Eigen::MatrixXd::Random(n, n);
  const Eigen::MatrixXd dense = g * g.transpose() + n * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd lower_dense = dense.triangularView<Eigen::Lower>();
  const Eigen::SparseMatrix<double> lower = lower_dense.sparseView();
  const LowerCsc m = test::to_lower_csc(lower);
  std::vector<int> given(n);
  for (int i = 0; i < n; ++i) given[static_cast<std::size_t>(i)] = i;
  CholmodFactor f;
  f.analyse_in_order(m, given);
  ASSERT_EQ(f.order(), given);
  ASSERT_TRUE(f.factorize(m));
  const Eigen::MatrixXd expected = dense.llt().matrixL().toDenseMatrix().bottomRightCorner(tail, tail);
  EXPECT_LE((f.trailing_block(tail) - expected).norm(), 1e-12 * expected.norm());
}

TEST(CholmodFactor, BisectionSeparatesTheTwoSides) {
  const LowerCsc m = test::to_lower_csc(test::grid_stiffness(20, 0.05));
  const std::vector<int> part = vertex_bisection(m);
  int counts[3] = {0, 0, 0};
  for (int p : part) ++counts[p];
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  // A 20 × 20 grid's best separator is a line of 20 nodes; METIS finds one within 2×.
  EXPECT_GT(counts[2], 0);
  EXPECT_LE(counts[2], 2 * 20 * 3);
  for (int c = 0; c < m.n; ++c)
    for (int k = m.start[static_cast<std::size_t>(c)]; k < m.start[static_cast<std::size_t>(c) + 1]; ++k) {
      const int pr = part[static_cast<std::size_t>(m.row[static_cast<std::size_t>(k)])], pc = part[static_cast<std::size_t>(c)];
      EXPECT_FALSE(pr != 2 && pc != 2 && pr != pc) << "entry (" << m.row[static_cast<std::size_t>(k)] << ", " << c << ")";
    }
  // A node's three unknowns stay together (the graph is compressed by node).
  for (int node = 0; node < m.n / 3; ++node) {
    EXPECT_EQ(part[static_cast<std::size_t>(3 * node)], part[static_cast<std::size_t>(3 * node + 1)]);
    EXPECT_EQ(part[static_cast<std::size_t>(3 * node)], part[static_cast<std::size_t>(3 * node + 2)]);
  }
}

}  // namespace
}  // namespace fabform::cholmod_factor_test
