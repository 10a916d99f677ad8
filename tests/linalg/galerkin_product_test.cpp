// The Galerkin product against Eigen's own products (PᵀA then ·P): the same matrix to rounding,
// on a fine grid's stiffness and the lattice's bilinear prolongation, and on random sparse
// factors; the same bits on one thread and on two; shapes that do not chain refused.
#include "linalg/galerkin_product.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "fabform/thread_count.hpp"
#include "linalg/lattice_prolongation.hpp"
#include "support/grid_stiffness.hpp"

namespace fabform {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

RowMatrix random_sparse(Eigen::Index rows, Eigen::Index columns, int per_row, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<Eigen::Index> column(0, columns - 1);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index r = 0; r < rows; ++r)
    for (int k = 0; k < per_row; ++k) entries.emplace_back(r, column(rng), value(rng));
  RowMatrix m(rows, columns);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

// Entry by entry within `relative` of the largest entry of |R||A||P| (what rounding scales with).
void expect_product(const RowMatrix& r, const RowMatrix& a, const RowMatrix& p, double relative) {
  const RowMatrix expected = RowMatrix(r * a) * p;
  const RowMatrix got = galerkin_product(r, a, p);
  const RowMatrix magnitude = RowMatrix(RowMatrix(r.cwiseAbs() * a.cwiseAbs()) * p.cwiseAbs());
  const double scale = Eigen::MatrixXd(magnitude).maxCoeff();
  EXPECT_LE((Eigen::MatrixXd(got) - Eigen::MatrixXd(expected)).cwiseAbs().maxCoeff(), relative * scale);
  EXPECT_TRUE(got.isCompressed());
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

TEST(GalerkinProduct, GivesTheSameBitsOnOneThreadAndOnTwo) {
  // 161 × 161 nodes: 3 · 81 · 81 = 19683 coarse rows, above the parallel loops' threshold.
  const RowMatrix a = test::symmetric(test::grid_stiffness(161, 0.2));
  const RowMatrix p = lattice_prolongation({161, 161});
  const RowMatrix r = p.transpose();
  ASSERT_GE(r.rows(), kMinParallelItems);
  use_threads(1);
  const RowMatrix one = galerkin_product(r, a, p);
  use_threads(2);
  const RowMatrix two = galerkin_product(r, a, p);
  use_threads(1);
  ASSERT_EQ(one.nonZeros(), two.nonZeros());
  EXPECT_TRUE(std::equal(one.valuePtr(), one.valuePtr() + one.nonZeros(), two.valuePtr()));
  EXPECT_TRUE(std::equal(one.innerIndexPtr(), one.innerIndexPtr() + one.nonZeros(), two.innerIndexPtr()));
}

TEST(GalerkinProduct, RefusesFactorsThatDoNotChain) {
  const RowMatrix a = random_sparse(6, 6, 2, 1), p = random_sparse(6, 3, 2, 2), r = random_sparse(3, 6, 2, 3);
  EXPECT_THROW(galerkin_product(r, random_sparse(6, 5, 2, 4), p), std::invalid_argument);
  EXPECT_THROW(galerkin_product(random_sparse(3, 5, 2, 5), a, p), std::invalid_argument);
  EXPECT_THROW(galerkin_product(random_sparse(2, 6, 2, 6), a, p), std::invalid_argument);
}

}  // namespace
}  // namespace fabform
