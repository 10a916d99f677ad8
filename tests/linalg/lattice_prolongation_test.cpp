// The lattice interpolation against the functions it must reproduce exactly: a bilinear field
// on the coarse lattice is that field on the fine one, for even and odd node counts (the last
// index is a coarse point either way); Newton's unknowns take its projection on their
// directions, and an unused slot takes nothing.
#include "linalg/lattice_prolongation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>

#include "fabform/thread_count.hpp"
#include "support/grid_stiffness.hpp"
#include "support/sparse_matrices.hpp"
#include "support/threads_restored.hpp"

namespace fabform::lattice_prolongation_test {
namespace {

// Where coarse index c sits among the fine indices of a lattice of n.
int fine_index(int c, int n) { return std::min(2 * c, n - 1); }

Eigen::Vector3d bilinear(double i, double j) {
  return {1.0 + 0.5 * i - 0.25 * j + 0.125 * i * j, -2.0 + 0.75 * j, 0.3 * i * j - i};
}

TEST(LatticeProlongation, CoarserLatticeKeepsEverySecondIndexAndTheLast) {
  EXPECT_EQ(coarser_lattice({5, 5}), (std::array<int, 2>{3, 3}));
  EXPECT_EQ(coarser_lattice({6, 9}), (std::array<int, 2>{4, 5}));
  EXPECT_EQ(coarser_lattice({2, 3}), (std::array<int, 2>{2, 2}));
  EXPECT_EQ(coarser_lattice({1001, 1001}), (std::array<int, 2>{501, 501}));
  EXPECT_THROW(coarser_lattice({1, 5}), std::invalid_argument);
}

TEST(LatticeProlongation, ReproducesABilinearFieldOnEvenAndOddLattices) {
  for (const std::array<int, 2> size : {std::array<int, 2>{5, 7}, {6, 9}, {8, 8}, {2, 3}}) {
    const std::array<int, 2> coarse = coarser_lattice(size);
    Eigen::VectorXd coarse_field(3 * coarse[0] * coarse[1]);
    for (int j = 0; j < coarse[1]; ++j)
      for (int i = 0; i < coarse[0]; ++i)
        coarse_field.segment<3>(3 * (i + coarse[0] * j)) = bilinear(fine_index(i, size[0]), fine_index(j, size[1]));
    const Eigen::VectorXd fine = lattice_prolongation(size) * coarse_field;
    for (int j = 0; j < size[1]; ++j)
      for (int i = 0; i < size[0]; ++i) {
        const Eigen::Vector3d expected = bilinear(i, j);
        // Sums of at most four products of numbers of order 10: rounding at 1e-14.
        EXPECT_LE((fine.segment<3>(3 * (i + size[0] * j)) - expected).norm(), 1e-13)
            << size[0] << " × " << size[1] << " at (" << i << ", " << j << ")";
      }
  }
}

TEST(LatticeProlongation, UnknownsAlongTheAxesAreTheLatticeInterpolation) {
  const RowMatrix by_unknowns = unknown_prolongation(test::grid_lattice(7));
  const RowMatrix by_lattice = lattice_prolongation({7, 7});
  EXPECT_EQ(Eigen::MatrixXd(by_unknowns), Eigen::MatrixXd(by_lattice));
}

TEST(LatticeProlongation, AnUnknownTakesTheInterpolatedMoveAlongItsDirection) {
  LatticeUnknowns l = test::grid_lattice(5);
  const Eigen::Vector3d tangent = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
  l.direction[3 * 7 + 1] = tangent;                // node (2, 1): a tangent direction
  l.direction[3 * 12 + 2] = Eigen::Vector3d::Zero();  // node (2, 2): a slot a contact normal took
  const std::array<int, 2> coarse = coarser_lattice({5, 5});
  Eigen::VectorXd coarse_field(3 * coarse[0] * coarse[1]);
  for (int j = 0; j < coarse[1]; ++j)
    for (int i = 0; i < coarse[0]; ++i) coarse_field.segment<3>(3 * (i + coarse[0] * j)) = bilinear(2 * i, 2 * j);
  const Eigen::VectorXd moves = unknown_prolongation(l) * coarse_field;
  EXPECT_NEAR(moves[3 * 7 + 1], tangent.dot(bilinear(2, 1)), 1e-13);
  EXPECT_EQ(moves[3 * 12 + 2], 0.0);
  EXPECT_NEAR(moves[3 * 12 + 0], bilinear(2, 2).x(), 1e-13);
}

// The matrices are written straight into Eigen's compressed arrays, so each row's columns must
// ascend (Eigen's products and iterators assume it). Directions with every component set give
// rows whose entries arrive out of column order (a coarse point's neighbour along j before its
// neighbour along i); every unknown must still take the interpolated move along its direction.
TEST(LatticeProlongation, RowsAreInColumnOrderAndEveryUnknownInterpolates) {
  LatticeUnknowns l = test::grid_lattice(6);
  for (std::size_t u = 0; u < l.direction.size(); ++u)
    if (u % 5 == 0) l.direction[u] = Eigen::Vector3d(0.3, -0.9, 0.2 + 0.01 * static_cast<double>(u)).normalized();
  l.direction[4] = Eigen::Vector3d::Zero();
  const RowMatrix by_unknowns = unknown_prolongation(l);
  const RowMatrix by_lattice = lattice_prolongation({6, 9});
  for (const RowMatrix* p : {&by_unknowns, &by_lattice}) {
    ASSERT_TRUE(p->isCompressed());
    for (Eigen::Index r = 0; r < p->outerSize(); ++r) {
      Eigen::Index last = -1;
      for (RowMatrix::InnerIterator it(*p, r); it; ++it) {
        EXPECT_GT(it.col(), last) << "row " << r;
        last = it.col();
      }
    }
  }
  const std::array<int, 2> coarse = coarser_lattice({6, 6});
  Eigen::VectorXd coarse_field(3 * coarse[0] * coarse[1]);
  for (int j = 0; j < coarse[1]; ++j)
    for (int i = 0; i < coarse[0]; ++i)
      coarse_field.segment<3>(3 * (i + coarse[0] * j)) = bilinear(fine_index(i, 6), fine_index(j, 6));
  const Eigen::VectorXd moves = by_unknowns * coarse_field;
  for (std::size_t u = 0; u < l.direction.size(); ++u) {
    const std::array<int, 2> ij = l.node_lattice[static_cast<std::size_t>(l.node[u])];
    // Sums of at most twelve products of numbers of order 10: rounding at 1e-14.
    EXPECT_NEAR(moves[static_cast<Eigen::Index>(u)], l.direction[u].dot(bilinear(ij[0], ij[1])), 1e-13) << "unknown " << u;
  }
}

// From 8192 rows both passes over the rows run on every thread: the same matrix, bit for bit, as
// on one (61 × 61 nodes, 11 163 unknowns, some directions oblique, one slot unused).
TEST(LatticeProlongation, SameMatrixOnOneThreadOrTwo) {
  LatticeUnknowns l = test::grid_lattice(61);
  ASSERT_GE(l.direction.size(), static_cast<std::size_t>(kMinParallelItems));
  for (std::size_t u = 0; u < l.direction.size(); ++u)
    if (u % 5 == 0) l.direction[u] = Eigen::Vector3d(0.3, -0.9, 0.2 + 1e-5 * static_cast<double>(u)).normalized();
  l.direction[4] = Eigen::Vector3d::Zero();
  const test::ThreadsRestored restored;
  use_threads(1);
  const RowMatrix unknowns_one = unknown_prolongation(l), lattice_one = lattice_prolongation({61, 70});
  use_threads(2);
  const RowMatrix unknowns_two = unknown_prolongation(l), lattice_two = lattice_prolongation({61, 70});
  EXPECT_TRUE(test::same_bits(unknowns_two, unknowns_one));
  EXPECT_TRUE(test::same_bits(lattice_two, lattice_one));
}

TEST(LatticeProlongation, RefusesADirectionPerUnknownMissing) {
  LatticeUnknowns l = test::grid_lattice(3);
  l.direction.pop_back();
  EXPECT_THROW(unknown_prolongation(l), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::lattice_prolongation_test
