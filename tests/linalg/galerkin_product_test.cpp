// The Galerkin product against Eigen's own products (PᵀA then ·P): the same matrix to rounding,
// on a fine grid's stiffness and the lattice's bilinear prolongation, and on random sparse
// factors, to the bit; the same bits in any blocks on any threads; each row's columns in order;
// shapes that do not chain refused.
#include "linalg/galerkin_product.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "fabform/thread_count.hpp"
#include "linalg/lattice_prolongation.hpp"
#include "support/grid_stiffness.hpp"
#include "support/sparse_matrices.hpp"
#include "support/threads_restored.hpp"

namespace fabform::galerkin_product_test {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

using test::random_sparse;
using test::same_bits;

// Entry by entry within `relative` of the largest entry of |R||A||P| (what rounding scales with).
void expect_product(const RowMatrix& r, const RowMatrix& a, const RowMatrix& p, double relative) {
  const RowMatrix expected = RowMatrix(r * a) * p;
  const RowMatrix got = galerkin_product(r, a, p);
  const RowMatrix magnitude = RowMatrix(RowMatrix(r.cwiseAbs() * a.cwiseAbs()) * p.cwiseAbs());
  const double scale = Eigen::MatrixXd(magnitude).maxCoeff();
  EXPECT_LE((Eigen::MatrixXd(got) - Eigen::MatrixXd(expected)).cwiseAbs().maxCoeff(), relative * scale);
}

TEST(GalerkinProduct, IsTheProductOfAGridStiffnessAndTheLatticeInterpolation) {
  const RowMatrix a = test::symmetric(test::grid_stiffness(9, 0.2));
  const RowMatrix p = lattice_prolongation({9, 9});
  const RowMatrix r = p.transpose();
  expect_product(r, a, p, 1e-14);
}

TEST(GalerkinProduct, IsTheProductOfRandomSparseFactors) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const RowMatrix a = random_sparse(60, 60, 5, seed);
    const RowMatrix p = random_sparse(60, 17, 3, seed + 10);
    const RowMatrix r = random_sparse(17, 60, 4, seed + 20);  // need not be Pᵀ
    expect_product(r, a, p, 1e-14);
  }
}

TEST(GalerkinProduct, GivesEigensBitsWhateverTheBlocksAndThreads) {
  // 81 × 81 nodes: 3 · 41 · 41 = 5043 coarse rows; 129 × 129 nodes, 12675 rows. In one block,
  // in blocks of 100 (the last one short) and of 1, on one thread and on two (the loop runs on
  // every thread from two blocks; one block alone on one).
  static_assert(3 * 41 * 41 > 4 * kGalerkinBlockRows, "the default blocks are shared out");
  const test::ThreadsRestored restored;
  for (const int side : {81, 129}) {
    const RowMatrix a = test::symmetric(test::grid_stiffness(side, 0.2));
    const RowMatrix p = lattice_prolongation({side, side});
    const RowMatrix r = p.transpose();
    use_threads(1);
    const RowMatrix whole = galerkin_product(r, a, p, r.rows());
    EXPECT_TRUE(same_bits(whole, RowMatrix(RowMatrix(r * a) * p))) << side;
    EXPECT_TRUE(same_bits(galerkin_product(r, a, p, 100), whole)) << side;
    EXPECT_TRUE(same_bits(galerkin_product(r, a, p, 1), whole)) << side;
    use_threads(2);
    EXPECT_TRUE(same_bits(galerkin_product(r, a, p, r.rows()), whole)) << side;
    EXPECT_TRUE(same_bits(galerkin_product(r, a, p, 100), whole)) << side;
    EXPECT_TRUE(same_bits(galerkin_product(r, a, p), whole)) << side;
  }
}

TEST(GalerkinProduct, ListsEachRowsColumnsInIncreasingOrder) {
  // Eigen's look-ups (coeff, coeffRef) search a row's columns by bisection.
  const RowMatrix a = random_sparse(200, 200, 7, 3), p = random_sparse(200, 50, 4, 4), r = random_sparse(50, 200, 9, 5);
  const RowMatrix c = galerkin_product(r, a, p, 7);
  for (Eigen::Index row = 0; row < c.rows(); ++row)
    EXPECT_TRUE(std::is_sorted(c.innerIndexPtr() + c.outerIndexPtr()[row], c.innerIndexPtr() + c.outerIndexPtr()[row + 1]))
        << row;
  EXPECT_TRUE(same_bits(c, RowMatrix(RowMatrix(r * a) * p)));
}

TEST(GalerkinProduct, RefusesFactorsThatDoNotChain) {
  const RowMatrix a = random_sparse(6, 6, 2, 1), p = random_sparse(6, 3, 2, 2), r = random_sparse(3, 6, 2, 3);
  EXPECT_THROW(galerkin_product(r, random_sparse(6, 5, 2, 4), p), std::invalid_argument);
  EXPECT_THROW(galerkin_product(random_sparse(3, 5, 2, 5), a, p), std::invalid_argument);
  EXPECT_THROW(galerkin_product(random_sparse(2, 6, 2, 6), a, p), std::invalid_argument);
  EXPECT_THROW(galerkin_product(r, a, p, 0), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::galerkin_product_test
