// The lattice multigrid against what a preconditioner for conjugate gradients must be and do:
// its V-cycle symmetric and positive definite; the residual it claims the one it leaves; a
// tight solve the direct answer (Eigen's LDLT), with slots a contact normal took and tangent
// directions among the unknowns; iterations that do not grow with the grid on a tensioned
// membrane, whose out-of-plane stiffness is a thousandth of its in-plane one, where algebraic
// multigrid (hypre's BoomerAMG) needs many more.
#include "linalg/lattice_multigrid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include "linalg/amg_conjugate_gradient.hpp"
#include "support/grid_stiffness.hpp"

namespace fabform::lattice_multigrid_test {
namespace {

struct System {
  Eigen::SparseMatrix<double> lower;  // over the unknowns, as Newton hands it over
  LatticeUnknowns unknowns;
};

// A square membrane of side × side nodes on a spherical cap (radius 2 sides), springs along the
// lattice and its diagonals, each of stiffness 1 along itself and `tension` across (a taut
// spring's geometric stiffness), its rim held. Nodes whose index is a multiple of `pressed`
// press on the cap: one slot along each tangent, the third taken by the normal (zero).
System membrane(int side, double tension, int pressed = 0) {
  const int n = side * side;
  const double radius = 2.0 * side;
  std::vector<Eigen::Vector3d> x(static_cast<std::size_t>(n));
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const double u = i - 0.5 * (side - 1), v = j - 0.5 * (side - 1);
      x[static_cast<std::size_t>(j * side + i)] = {u, v, std::sqrt(radius * radius - u * u - v * v)};
    }
  std::vector<Eigen::Triplet<double>> full;
  const auto spring = [&](int a, int b) {
    const Eigen::Vector3d e = (x[static_cast<std::size_t>(b)] - x[static_cast<std::size_t>(a)]).normalized();
    const Eigen::Matrix3d k = e * e.transpose() + tension * (Eigen::Matrix3d::Identity() - e * e.transpose());
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        full.emplace_back(3 * a + r, 3 * a + c, k(r, c));
        full.emplace_back(3 * b + r, 3 * b + c, k(r, c));
        full.emplace_back(3 * a + r, 3 * b + c, -k(r, c));
        full.emplace_back(3 * b + r, 3 * a + c, -k(r, c));
      }
  };
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const int k = j * side + i;
      if (i + 1 < side) spring(k, k + 1);
      if (j + 1 < side) spring(k, k + side);
      if (i + 1 < side && j + 1 < side) spring(k, k + side + 1), spring(k + 1, k + side);
    }
  Eigen::SparseMatrix<double> a(3 * n, 3 * n);
  a.setFromTriplets(full.begin(), full.end());

  System s{{}, test::grid_lattice(side)};
  std::vector<Eigen::Triplet<double>> basis;
  for (int k = 0; k < n; ++k) {
    const int i = k % side, j = k / side;
    const bool rim = i == 0 || j == 0 || i == side - 1 || j == side - 1;
    Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
    if (rim) d.setZero();
    else if (pressed > 0 && k % pressed == 0) {
      const Eigen::Vector3d normal = x[static_cast<std::size_t>(k)].normalized();
      d.col(0) = (Eigen::Vector3d::UnitX() - normal.x() * normal).normalized();
      d.col(1) = normal.cross(d.col(0));
      d.col(2).setZero();
    }
    for (int c = 0; c < 3; ++c) {
      s.unknowns.direction[static_cast<std::size_t>(3 * k + c)] = d.col(c);
      for (int r = 0; r < 3; ++r)
        if (d(r, c) != 0.0) basis.emplace_back(3 * k + r, 3 * k + c, d(r, c));
    }
  }
  Eigen::SparseMatrix<double> dm(3 * n, 3 * n);
  dm.setFromTriplets(basis.begin(), basis.end());
  Eigen::SparseMatrix<double> reduced = Eigen::SparseMatrix<double>(dm.transpose() * a) * dm;
  // A slot with no direction: an empty row and column, and Newton's regularisation's diagonal.
  for (int u = 0; u < 3 * n; ++u)
    if (s.unknowns.direction[static_cast<std::size_t>(u)].isZero(0.0)) reduced.coeffRef(u, u) = 1.0;
  s.lower = reduced.triangularView<Eigen::Lower>();
  s.lower.makeCompressed();
  return s;
}

Eigen::VectorXd load(Eigen::Index n, unsigned seed = 3) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = unit(rng);
  return b;
}

TEST(LatticeMultigrid, TheVCycleIsSymmetricAndPositiveDefinite) {
  const System s = membrane(65, 1e-3, 3);
  LatticeMultigrid mg;
  mg.set_matrix(s.lower, s.unknowns);
  EXPECT_GE(mg.levels(), 3);
  const Eigen::VectorXd u = load(s.lower.rows(), 1), v = load(s.lower.rows(), 2);
  const double uv = u.dot(mg.v_cycle(v)), vu = v.dot(mg.v_cycle(u));
  // Rounding in a few thousand sums of products: 1e-10 of the size of either.
  EXPECT_NEAR(uv, vu, 1e-10 * (std::abs(uv) + std::abs(vu)));
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Eigen::VectorXd w = load(s.lower.rows(), seed);
    EXPECT_GT(w.dot(mg.v_cycle(w)), 0.0) << seed;
  }
}

TEST(LatticeMultigrid, LeavesTheResidualItClaims) {
  const System s = membrane(40, 1e-3, 4);
  const Eigen::SparseMatrix<double> a = test::symmetric(s.lower);
  LatticeMultigrid mg;
  mg.set_matrix(s.lower, s.unknowns);
  const Eigen::VectorXd b = load(s.lower.rows());
  for (double tolerance : {1e-1, 1e-4, 1e-8}) {
    const CgResult r = mg.solve(b, tolerance, 500);
    const double residual = (b - a * r.x).norm() / b.norm();
    EXPECT_LE(residual, tolerance * (1.0 + 1e-6)) << tolerance;
    // The recurrence's residual drifts from the recomputed one by rounding alone.
    EXPECT_NEAR(r.relative_residual, residual, 1e-12 + 1e-6 * residual) << tolerance;
    EXPECT_GT(r.iterations, 0);
  }
}

TEST(LatticeMultigrid, ATightToleranceGivesTheDirectAnswerWithContactSlots) {
  const System s = membrane(25, 1e-2, 2);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> direct(s.lower);
  ASSERT_EQ(direct.info(), Eigen::Success);
  const Eigen::VectorXd b = load(s.lower.rows());
  const Eigen::VectorXd exact = direct.solve(b);
  LatticeMultigrid mg;
  mg.set_matrix(s.lower, s.unknowns);
  const CgResult r = mg.solve(b, 1e-13, 1000);
  // The error is at most the condition number (≲ 1e5 here) times the residual.
  EXPECT_LE((r.x - exact).lpNorm<Eigen::Infinity>(), 1e-7 * exact.lpNorm<Eigen::Infinity>());
}

TEST(LatticeMultigrid, IterationsDoNotGrowWithTheGrid) {
  const auto iterations = [](int side) {
    const System s = membrane(side, 1e-3, 3);
    LatticeMultigrid mg;
    mg.set_matrix(s.lower, s.unknowns);
    return mg.solve(load(s.lower.rows()), 1e-8, 1000).iterations;
  };
  const int small = iterations(33), even = iterations(64), large = iterations(129);  // 3 267 to 49 923 unknowns
  EXPECT_LE(large, small + small / 2 + 2) << small << " on 33 × 33, " << large << " on 129 × 129";
  EXPECT_LE(even, small + small / 2 + 2) << small << " on 33 × 33, " << even << " on 64 × 64";
}

TEST(LatticeMultigrid, HoldsTheSoftModesThatAlgebraicMultigridMisses) {
  const System s = membrane(65, 1e-3, 3);
  const Eigen::VectorXd b = load(s.lower.rows());
  LatticeMultigrid lattice;
  lattice.set_matrix(s.lower, s.unknowns);
  AmgConjugateGradient algebraic;
  algebraic.set_matrix(s.lower, test::xyz_components(s.lower.rows()));
  const int geometric = lattice.solve(b, 1e-8, 1000).iterations;
  const int amg = algebraic.solve(b, 1e-8, 1000).iterations;
  EXPECT_LT(2 * geometric, amg) << geometric << " lattice, " << amg << " BoomerAMG";
}

TEST(LatticeMultigrid, AnyIterateIsADescentDirection) {
  const System s = membrane(20, 1e-4, 3);
  LatticeMultigrid mg;
  mg.set_matrix(s.lower, s.unknowns);
  const Eigen::VectorXd b = load(s.lower.rows());
  for (int cap : {1, 2, 5}) {
    const CgResult r = mg.solve(b, 1e-14, cap);
    EXPECT_EQ(r.iterations, cap);
    EXPECT_GT(r.x.dot(b), 0.0) << cap;
    EXPECT_TRUE(r.x.allFinite());
  }
}

TEST(LatticeMultigrid, ZeroLoadIsZeroStep) {
  const System s = membrane(9, 1e-3);
  LatticeMultigrid mg;
  mg.set_matrix(s.lower, s.unknowns);
  const CgResult r = mg.solve(Eigen::VectorXd::Zero(s.lower.rows()), 1e-8, 100);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_TRUE(r.x.isZero(0.0));
}

TEST(LatticeMultigrid, RefusesMisuse) {
  const System s = membrane(6, 1e-3);
  LatticeMultigrid mg;
  EXPECT_THROW(mg.solve(load(s.lower.rows()), 1e-8, 10), std::logic_error);
  LatticeUnknowns short_of_one = s.unknowns;
  short_of_one.node.pop_back();
  EXPECT_THROW(mg.set_matrix(s.lower, short_of_one), std::invalid_argument);
  mg.set_matrix(s.lower, s.unknowns);
  EXPECT_THROW(mg.solve(load(s.lower.rows() - 1), 1e-8, 10), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::lattice_multigrid_test
