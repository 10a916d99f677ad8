// The diagonal read and written on every thread against Eigen's own diagonal() (the brute force
// here): the same values, bit for bit, on one thread and on several, both storage orders, square
// and not, compressed and not, with diagonal entries missing, on sizes from empty to those where
// the work is shared (8192 rows); the in-order sum against Eigen's sum of a sparse diagonal; a
// write to a diagonal entry that is not stored refused.
#include "linalg/sparse_diagonal.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "fabform/thread_count.hpp"
#include "support/sparse_matrices.hpp"
#include "support/threads_restored.hpp"

namespace fabform::sparse_diagonal_test {
namespace {

using ColumnMatrix = Eigen::SparseMatrix<double>;
using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// An empty vector's data() is null, which memcmp must not be given.
bool same_bits(const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  return x.size() == y.size() &&
         (x.size() == 0 || std::memcmp(x.data(), y.data(), sizeof(double) * static_cast<std::size_t>(x.size())) == 0);
}

// Random entries, every seventh row empty (so its diagonal entry is missing too).
template <class Matrix>
Matrix random_matrix(Eigen::Index rows, Eigen::Index columns, unsigned seed) {
  return Matrix(test::random_sparse(rows, columns, 6, seed, 7));
}

template <class Matrix>
void expect_eigens_diagonal(const Matrix& m) {
  const Eigen::VectorXd eigens = m.diagonal();
  const Eigen::VectorXd ours = stored_diagonal(m, diagonal_positions(m));
  EXPECT_TRUE(same_bits(ours, eigens));
}

struct Shape {
  Eigen::Index rows, columns;
};
static_assert(9000 > kMinParallelItems, "the largest shape is shared among threads");
constexpr Shape kShapes[] = {{0, 0}, {1, 1}, {5, 9}, {9, 5}, {60, 60}, {9000, 9000}, {9000, 8500}};

TEST(SparseDiagonal, IsEigensDiagonalInBothStorageOrders) {
  test::on_thread_counts({1, 2, 3}, [] {
    for (const Shape s : kShapes)
      for (unsigned seed = 1; seed <= 2; ++seed) {
        SCOPED_TRACE(testing::Message() << s.rows << " x " << s.columns << ", seed " << seed);
        expect_eigens_diagonal(random_matrix<RowMatrix>(s.rows, s.columns, seed));
        expect_eigens_diagonal(random_matrix<ColumnMatrix>(s.rows, s.columns, seed));
      }
  });
}

TEST(SparseDiagonal, ReadsAnUncompressedMatrix) {
  // Room reserved in every column, then entries inserted: Eigen keeps it uncompressed, with
  // stale slots past each column's entries that must not be read as the diagonal.
  ColumnMatrix m(50, 50);
  m.reserve(Eigen::VectorXi::Constant(50, 4));
  for (int k = 0; k < 50; ++k) {
    if (k % 3 != 0) m.insert(k, k) = 1.0 + k;
    m.insert((k + 7) % 50, k) = -0.5;
  }
  ASSERT_FALSE(m.isCompressed());
  expect_eigens_diagonal(m);
}

TEST(SparseDiagonal, MissingEntriesAreMarked) {
  ColumnMatrix m(4, 4);
  m.insert(0, 0) = 2.0;
  m.insert(2, 1) = 3.0;
  m.insert(3, 3) = 4.0;
  m.makeCompressed();
  const std::vector<Eigen::Index> positions = diagonal_positions(m);
  ASSERT_EQ(positions.size(), 4u);
  EXPECT_EQ(positions[1], -1);
  EXPECT_EQ(positions[2], -1);
  EXPECT_EQ(m.valuePtr()[positions[3]], 4.0);
}

TEST(SparseDiagonal, ShiftedDiagonalIsEigensAssignment) {
  test::on_thread_counts({1, 2, 3}, [] {
    for (const Eigen::Index n : {1, 60, 9000}) {
      SCOPED_TRACE(testing::Message() << n << " rows");
      // Every diagonal entry stored: the random entries plus an identity.
      ColumnMatrix ours = random_matrix<ColumnMatrix>(n, n, 3);
      ColumnMatrix identity(n, n);
      identity.setIdentity();
      ours += identity;
      ColumnMatrix eigens = ours;
      const std::vector<Eigen::Index> positions = diagonal_positions(ours);
      const Eigen::VectorXd d = stored_diagonal(ours, positions);
      const double shift = 0.1 * sum_in_order(d) / static_cast<double>(n);
      set_shifted_diagonal(ours, positions, d, shift);
      eigens.diagonal() = d.array() + shift;
      ASSERT_EQ(ours.nonZeros(), eigens.nonZeros());
      EXPECT_EQ(std::memcmp(ours.valuePtr(), eigens.valuePtr(), sizeof(double) * static_cast<std::size_t>(ours.nonZeros())), 0);
    }
  });
}

TEST(SparseDiagonal, ShiftRefusedWhereAnEntryIsMissing) {
  ColumnMatrix m(3, 3);
  m.insert(0, 0) = 1.0;
  m.insert(2, 2) = 1.0;
  m.makeCompressed();
  const std::vector<Eigen::Index> positions = diagonal_positions(m);
  EXPECT_THROW(set_shifted_diagonal(m, positions, Eigen::VectorXd::Ones(3), 1.0), std::invalid_argument);
  EXPECT_THROW(set_shifted_diagonal(m, positions, Eigen::VectorXd::Ones(2), 1.0), std::invalid_argument);
}

TEST(SparseDiagonal, SumInOrderIsEigensSparseDiagonalSum) {
  // A sparse diagonal is summed one entry after another; a dense vector's sum() is vectorised and
  // differs in the last bits for values like these.
  const RowMatrix m = random_matrix<RowMatrix>(9000, 9000, 5) * 1e3;
  const Eigen::VectorXd d = stored_diagonal(m, diagonal_positions(m));
  const double eigens = m.diagonal().sum();
  EXPECT_EQ(sum_in_order(d), eigens);
}

}  // namespace
}  // namespace fabform::sparse_diagonal_test
