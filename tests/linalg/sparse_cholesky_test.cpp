// Newton's sparse Cholesky: the same answer, bit for bit, on one thread and on two, whether it
// splits the matrix or not; a new pattern is analysed anew; a matrix in uncompressed storage is
// factorised as its compressed copy is.
#include "linalg/sparse_cholesky.hpp"

#include <gtest/gtest.h>

#include "fabform/thread_count.hpp"
#include "support/grid_stiffness.hpp"

namespace fabform::sparse_cholesky_test {
namespace {

// Newton splits from 300 000 unknowns; these tests from 2000, to stay small.
constexpr int kMinimum = 2000;

Eigen::VectorXd solved_on(int threads, const Eigen::SparseMatrix<double>& lower) {
  use_threads(threads);
  SparseCholesky cholesky(kMinimum);
  EXPECT_TRUE(cholesky.factorize(lower));
  EXPECT_EQ(cholesky.split(), lower.rows() >= kMinimum);
  Eigen::VectorXd b(lower.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = 1.0 / (1.0 + static_cast<double>(i % 17));
  return cholesky.solve(b);
}

TEST(SparseCholesky, ThreadCountDoesNotChangeABit) {
  const int before = threads_in_use();
  for (int side : {10, 30}) {  // below and above the split's minimum size
    const Eigen::SparseMatrix<double> lower = test::grid_stiffness(side, 0.01);
    const Eigen::VectorXd one = solved_on(1, lower), two = solved_on(2, lower);
    use_threads(before);  // the tests after this one, in the same process, run as they would alone
    EXPECT_TRUE(one == two) << side << " × " << side;
    const Eigen::SparseMatrix<double> a = test::symmetric(lower);
    Eigen::VectorXd b(lower.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = 1.0 / (1.0 + static_cast<double>(i % 17));
    EXPECT_LE((a * one - b).norm(), 1e-10 * b.norm());
  }
}

TEST(SparseCholesky, AnalysesANewPattern) {
  SparseCholesky cholesky(kMinimum);
  for (int side : {30, 10, 31}) {
    const Eigen::SparseMatrix<double> lower = test::grid_stiffness(side, 0.01);
    ASSERT_TRUE(cholesky.factorize(lower));
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(lower.rows());
    EXPECT_LE((test::symmetric(lower) * cholesky.solve(b) - b).norm(), 1e-10 * b.norm()) << side;
  }
}

// Inserting an entry leaves Eigen's storage uncompressed (room kept per column): the factorisation
// reads it as compressed, bit for bit.
TEST(SparseCholesky, AnUncompressedMatrixIsFactorisedAsItsCompressedCopy) {
  Eigen::SparseMatrix<double> loose = test::grid_stiffness(10, 0.01);
  loose.coeffRef(loose.rows() - 1, 0) = 1e-3;  // a new entry, in the lower triangle
  ASSERT_FALSE(loose.isCompressed());
  Eigen::SparseMatrix<double> tight = loose;
  tight.makeCompressed();
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(loose.rows());
  SparseCholesky from_loose(kMinimum), from_tight(kMinimum);
  ASSERT_TRUE(from_loose.factorize(loose));
  ASSERT_TRUE(from_tight.factorize(tight));
  EXPECT_TRUE(from_loose.solve(b) == from_tight.solve(b));
  EXPECT_LE((test::symmetric(tight) * from_loose.solve(b) - b).norm(), 1e-10 * b.norm());
}

}  // namespace
}  // namespace fabform::sparse_cholesky_test
