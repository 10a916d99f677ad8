// The Galerkin product against Eigen's own products (PᵀA then ·P): the same matrix to rounding,
// on a fine grid's stiffness and the lattice's bilinear prolongation, and on random sparse
// factors; in blocks, the whole product's bits; shapes that do not chain refused.
#include "linalg/galerkin_product.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

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

TEST(GalerkinProduct, GivesTheBitsOfTheWholeProductInBlocks) {
  // 41 × 41 nodes: 3 · 21 · 21 = 1323 coarse rows, in blocks of 100 (the last one short),
  // against Eigen's products of the whole matrices.
  const RowMatrix a = test::symmetric(test::grid_stiffness(41, 0.2));
  const RowMatrix p = lattice_prolongation({41, 41});
  const RowMatrix r = p.transpose();
  const RowMatrix blocks = galerkin_product(r, a, p, 100), whole = RowMatrix(r * a) * p;
  ASSERT_EQ(blocks.nonZeros(), whole.nonZeros());
  EXPECT_TRUE(std::equal(blocks.valuePtr(), blocks.valuePtr() + blocks.nonZeros(), whole.valuePtr()));
  EXPECT_TRUE(std::equal(blocks.innerIndexPtr(), blocks.innerIndexPtr() + blocks.nonZeros(), whole.innerIndexPtr()));
  EXPECT_TRUE(std::equal(blocks.outerIndexPtr(), blocks.outerIndexPtr() + blocks.rows() + 1, whole.outerIndexPtr()));
}

TEST(GalerkinProduct, RefusesFactorsThatDoNotChain) {
  const RowMatrix a = random_sparse(6, 6, 2, 1), p = random_sparse(6, 3, 2, 2), r = random_sparse(3, 6, 2, 3);
  EXPECT_THROW(galerkin_product(r, random_sparse(6, 5, 2, 4), p), std::invalid_argument);
  EXPECT_THROW(galerkin_product(random_sparse(3, 5, 2, 5), a, p), std::invalid_argument);
  EXPECT_THROW(galerkin_product(random_sparse(2, 6, 2, 6), a, p), std::invalid_argument);
  EXPECT_THROW(galerkin_product(r, a, p, 0), std::invalid_argument);
}

}  // namespace
}  // namespace fabform
