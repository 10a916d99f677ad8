// Line Gauss–Seidel against what a line smoother must be: a matrix whose couplings all run along
// one lattice direction is solved exactly by one sweep, whichever the direction; a forward sweep
// and a backward one, from zero, are a symmetric positive operator; sweeps converge to the
// direct solution (Eigen's LDLT); a level large enough to be swept in two halves at once is all
// of these too, with the same bits on any thread count; a lattice point with no stiffness and no
// load stays put.
#include "linalg/line_gauss_seidel.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/SparseCholesky>

#include "fabform/thread_count.hpp"
#include "support/grid_stiffness.hpp"
#include "support/threads_restored.hpp"

namespace fabform::line_gauss_seidel_test {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Each unknown's lattice point on test::grid_stiffness's grid (node j·side + i at (i, j)).
std::vector<std::array<int, 2>> grid_places(int side) {
  const LatticeUnknowns lattice = test::grid_lattice(side);
  std::vector<std::array<int, 2>> place;
  for (const int node : lattice.node) place.push_back(lattice.node_lattice[static_cast<std::size_t>(node)]);
  return place;
}

Eigen::VectorXd load(Eigen::Index n) {
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = std::cos(0.7 * static_cast<double>(i));
  return b;
}

Eigen::VectorXd direct_solution(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b) {
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(a);
  return direct.solve(b);
}

// x after a forward sweep and a backward one from zero: the smoother as an operator on b.
Eigen::VectorXd symmetric_sweep(const LineGaussSeidel& s, const RowMatrix& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  s.sweep(a, b, x, true);
  s.sweep(a, b, x, false);
  return x;
}

TEST(LineGaussSeidel, SolvesCouplingsAlongEitherDirectionInOneSweep) {
  const int side = 7;
  for (const int along : {0, 1}) {
    // The grid's springs across the lines dropped; what they added to the diagonal kept.
    Eigen::SparseMatrix<double> a = test::symmetric(test::grid_stiffness(side, 0.05));
    a.prune([&](Eigen::Index row, Eigen::Index column, double) {
      const auto across = [&](Eigen::Index u) { return along == 0 ? u / 3 / side : u / 3 % side; };
      return across(row) == across(column);
    });
    const RowMatrix rows = a;
    const LineGaussSeidel s(rows, grid_places(side));
    const Eigen::VectorXd b = load(a.rows());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    s.sweep(rows, b, x, true);
    const Eigen::VectorXd exact = direct_solution(a, b);
    // The lines' diagonal shift (1e-10 of the mean) is the only difference.
    EXPECT_LE((x - exact).norm(), 1e-8 * exact.norm()) << "lines along " << (along == 0 ? "i" : "j");
  }
}

TEST(LineGaussSeidel, AForwardAndABackwardSweepAreSymmetricAndPositive) {
  const RowMatrix a = test::symmetric(test::grid_stiffness(9, 0.01));
  const LineGaussSeidel s(a, grid_places(9));
  const Eigen::VectorXd u = load(a.rows()), v = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  const double uv = u.dot(symmetric_sweep(s, a, v)), vu = v.dot(symmetric_sweep(s, a, u));
  EXPECT_NEAR(uv, vu, 1e-12 * (std::abs(uv) + std::abs(vu)));
  EXPECT_GT(u.dot(symmetric_sweep(s, a, u)), 0.0);
  EXPECT_GT(v.dot(symmetric_sweep(s, a, v)), 0.0);
}

TEST(LineGaussSeidel, SweepsConvergeToTheDirectSolution) {
  const Eigen::SparseMatrix<double> a = test::symmetric(test::grid_stiffness(6, 0.5));
  const RowMatrix rows = a;
  const LineGaussSeidel s(rows, grid_places(6));
  const Eigen::VectorXd b = load(a.rows());
  const Eigen::VectorXd exact = direct_solution(a, b);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  for (int k = 0; k < 100; ++k) s.sweep(rows, b, x, k % 2 == 0);
  // The fixed point is the solution of the shifted lines' splitting, which is a's own.
  EXPECT_LE((x - exact).norm(), 1e-9 * exact.norm());
}

// A level large enough to be swept in two halves and a seam (3 · 60 · 60 = 10800 unknowns), with
// couplings one line across (the grid's springs) and two (its square's, shifted to converge in
// as few sweeps).
std::vector<RowMatrix> large_levels() {
  static_assert(3 * 60 * 60 >= kMinParallelItems, "a level the sweep splits");
  const RowMatrix a = test::symmetric(test::grid_stiffness(60, 0.5));
  RowMatrix identity(a.rows(), a.cols());
  identity.setIdentity();
  return {a, RowMatrix(a * a) + 4.0 * identity};
}

TEST(LineGaussSeidel, ALargeLevelSweptInHalvesIsSymmetricPositiveAndConverges) {
  for (const RowMatrix& a : large_levels()) {
    const LineGaussSeidel s(a, grid_places(60));
    const Eigen::VectorXd u = load(a.rows()), v = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
    const double uv = u.dot(symmetric_sweep(s, a, v)), vu = v.dot(symmetric_sweep(s, a, u));
    EXPECT_NEAR(uv, vu, 1e-12 * (std::abs(uv) + std::abs(vu)));
    EXPECT_GT(u.dot(symmetric_sweep(s, a, u)), 0.0);
    const Eigen::VectorXd exact = direct_solution(Eigen::SparseMatrix<double>(a), u);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(u.size());
    for (int k = 0; k < 200; ++k) s.sweep(a, u, x, k % 2 == 0);
    EXPECT_LE((x - exact).norm(), 1e-9 * exact.norm());
  }
}

TEST(LineGaussSeidel, ALargeLevelGivesTheSameBitsOnOneThreadAndTwo) {
  const test::ThreadsRestored restored;
  for (const RowMatrix& a : large_levels()) {
    const LineGaussSeidel s(a, grid_places(60));
    const Eigen::VectorXd b = load(a.rows());
    use_threads(1);
    const Eigen::VectorXd one = symmetric_sweep(s, a, b);
    use_threads(2);
    const Eigen::VectorXd two = symmetric_sweep(s, a, b);
    EXPECT_TRUE(one == two);
  }
}

TEST(LineGaussSeidel, APointWithNoStiffnessAndNoLoadStaysPut) {
  const int side = 4;
  RowMatrix a = test::symmetric(test::grid_stiffness(side, 0.1));
  const int still = 3 * (side + 1);  // the node at (1, 1), amid the others
  a.prune([&](Eigen::Index row, Eigen::Index column, double) {
    return (row < still || row >= still + 3) && (column < still || column >= still + 3);
  });
  const LineGaussSeidel s(a, grid_places(side));
  Eigen::VectorXd b = load(a.rows());
  b.segment<3>(still).setZero();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(a.rows());
  for (int k = 0; k < 4; ++k) s.sweep(a, b, x, k % 2 == 0);
  EXPECT_TRUE(x.segment<3>(still).isZero(0.0));
  EXPECT_TRUE(x.allFinite());
}

TEST(LineGaussSeidel, AnEmptyLevelSweepsToNothing) {
  const RowMatrix a(0, 0);
  const LineGaussSeidel s(a, {});
  Eigen::VectorXd x(0);
  s.sweep(a, Eigen::VectorXd(0), x, true);
  EXPECT_EQ(x.size(), 0);
}

TEST(LineGaussSeidel, RefusesToSweepAnotherMatrix) {
  // Its lines' seams were placed by the couplings of the matrix it was made from.
  const RowMatrix a = test::symmetric(test::grid_stiffness(5, 0.1)), wider = RowMatrix(a * a);
  const LineGaussSeidel s(a, grid_places(5));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(a.rows());
  EXPECT_THROW(s.sweep(wider, load(a.rows()), x, true), std::invalid_argument);
}

TEST(LineGaussSeidel, RefusesPlacesThatDoNotFit) {
  const RowMatrix a = test::symmetric(test::grid_stiffness(2, 0.1));
  std::vector<std::array<int, 2>> places = grid_places(2);
  places.pop_back();
  EXPECT_THROW(LineGaussSeidel(a, places), std::invalid_argument);  // 11 places, 12 unknowns
  places = grid_places(2);
  places[4] = {-1, 0};
  EXPECT_THROW(LineGaussSeidel(a, places), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::line_gauss_seidel_test
