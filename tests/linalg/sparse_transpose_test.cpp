// The parallel transposes against Eigen's own conversions (the brute force here): the same
// matrix, entry for entry and bit for bit, on one thread and on several, on shapes from empty to
// the sizes where the work is shared (8192 entries), square and not, with rows and columns
// left empty; a symmetric matrix's lower triangle expanded as Eigen's selfadjointView expands
// it, entries above the diagonal ignored; a matrix that is not square refused.
#include "linalg/sparse_transpose.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "fabform/thread_count.hpp"
#include "linalg/lattice_prolongation.hpp"
#include "support/grid_stiffness.hpp"
#include "support/sparse_matrices.hpp"
#include "support/threads_restored.hpp"

namespace fabform::sparse_transpose_test {
namespace {

using test::same_bits;

// Some rows left empty, and so, on wide shapes, some columns.
RowMatrix random_sparse(Eigen::Index rows, Eigen::Index columns, int per_row, unsigned seed) {
  return test::random_sparse(rows, columns, per_row, seed, 7);
}

// Runs `check` on one thread and on two, three and five (bands with both edges inside the
// matrix; more threads than cores is no matter here).
template <class Check>
void on_one_thread_and_more(Check check) {
  test::on_thread_counts({1, 2, 3, 5}, check);
}

TEST(SparseTranspose, IsEigensTransposeOnEveryShape) {
  struct Shape {
    Eigen::Index rows, columns;
    int per_row;
  };
  static_assert(3000 * 4 > kMinParallelItems, "the largest shape is shared among threads");
  on_one_thread_and_more([] {
    for (const Shape s : {Shape{0, 0, 0}, Shape{1, 1, 1}, Shape{1, 9, 4}, Shape{9, 1, 2}, Shape{40, 40, 5},
                          Shape{3000, 700, 4}, Shape{700, 3000, 16}})
      for (unsigned seed = 1; seed <= 2; ++seed) {
        SCOPED_TRACE(testing::Message() << s.rows << " x " << s.columns << ", seed " << seed);
        const RowMatrix a = random_sparse(s.rows, s.columns, s.per_row, seed);
        EXPECT_TRUE(same_bits(transposed(a), RowMatrix(a.transpose())));
      }
  });
}

TEST(SparseTranspose, TransposesTheLatticeInterpolation) {
  // The restriction the multigrid keeps, on a lattice large enough to share.
  const RowMatrix p = lattice_prolongation({129, 129});
  ASSERT_GE(p.nonZeros(), kMinParallelItems);
  on_one_thread_and_more([&] { EXPECT_TRUE(same_bits(transposed(p), RowMatrix(p.transpose()))); });
}

TEST(SparseTranspose, TakesAnUncompressedMatrix) {
  RowMatrix a = random_sparse(30, 20, 3, 5);
  a.coeffRef(4, 7) += 1.0;  // an insertion leaves Eigen's matrix uncompressed
  a.coeffRef(4, 7) -= 1.0;
  a.coeffRef(29, 19) = 2.5;
  ASSERT_FALSE(a.isCompressed());
  RowMatrix b = a;
  b.makeCompressed();
  EXPECT_TRUE(same_bits(transposed(a), RowMatrix(b.transpose())));
  EXPECT_EQ(Eigen::MatrixXd(transposed(a)), Eigen::MatrixXd(b).transpose());
}

TEST(WholeSymmetric, IsEigensSelfadjointExpansion) {
  on_one_thread_and_more([] {
    for (const int side : {1, 4, 40}) {  // 40 × 40 nodes: 120 unknowns a row of nodes, 28 000 entries
      SCOPED_TRACE(testing::Message() << side << " x " << side << " nodes");
      const Eigen::SparseMatrix<double> lower = test::grid_stiffness(side, 0.1);
      const RowMatrix expected = lower.selfadjointView<Eigen::Lower>();
      EXPECT_TRUE(same_bits(whole_symmetric(lower), expected));
    }
  });
}

TEST(WholeSymmetric, IgnoresEntriesAboveTheDiagonalAndMissingDiagonals) {
  // A lower triangle with holes on the diagonal, and entries above it that the expansion must
  // not read (Eigen's selfadjointView does not).
  on_one_thread_and_more([] {
    for (const Eigen::Index n : {Eigen::Index{5}, Eigen::Index{3000}}) {
      SCOPED_TRACE(testing::Message() << n << " unknowns");
      const Eigen::SparseMatrix<double> any = random_sparse(n, n, 6, 11);
      Eigen::SparseMatrix<double> lower = any;
      lower.makeCompressed();
      const RowMatrix expected = lower.selfadjointView<Eigen::Lower>();
      const RowMatrix got = whole_symmetric(lower);
      EXPECT_TRUE(same_bits(got, expected));
      if (n < 10) {  // and as a dense matrix, the brute force
        const Eigen::MatrixXd dense = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
        EXPECT_EQ(Eigen::MatrixXd(got), dense);
      }
    }
  });
}

TEST(WholeSymmetric, TakesAnUncompressedMatrix) {
  Eigen::SparseMatrix<double> lower = test::grid_stiffness(4, 0.1);
  lower.coeffRef(47, 0) = 0.25;  // an insertion leaves Eigen's matrix uncompressed
  ASSERT_FALSE(lower.isCompressed());
  Eigen::SparseMatrix<double> compressed = lower;
  compressed.makeCompressed();
  EXPECT_TRUE(same_bits(whole_symmetric(lower), RowMatrix(compressed.selfadjointView<Eigen::Lower>())));
}

TEST(WholeSymmetric, RefusesAMatrixThatIsNotSquare) {
  const Eigen::SparseMatrix<double> tall = random_sparse(6, 4, 2, 1);
  EXPECT_THROW(whole_symmetric(tall), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::sparse_transpose_test
