// The banded LDLᵀ against Eigen's dense solve: random symmetric positive definite band matrices
// over every bandwidth from none to wider than the matrix, an indefinite one (negative pivots
// taken, as Eigen's LDLᵀ takes them), a zero pivot refused, and entries outside the band refused.
#include "linalg/banded_ldlt.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

#include <Eigen/Dense>

namespace fabform::banded_ldlt_test {
namespace {

// A random symmetric matrix of the given band, its diagonal the row's absolute sum times
// `dominance`, plus 1e-3 (dominance ≥ 1: positive definite).
Eigen::MatrixXd random_band(int n, int bandwidth, double dominance, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = std::max(0, r - bandwidth); c < r; ++c) a(r, c) = a(c, r) = entry(random);
  for (int r = 0; r < n; ++r) a(r, r) = dominance * a.row(r).cwiseAbs().sum() + 1e-3;
  return a;
}

BandedLdlt factorised(const Eigen::MatrixXd& a, int bandwidth) {
  const auto n = static_cast<int>(a.rows());
  BandedLdlt f(n, bandwidth);
  for (int r = 0; r < n; ++r)
    for (int c = std::max(0, r - f.bandwidth()); c <= r; ++c) f.at(r, c) = a(r, c);
  EXPECT_TRUE(f.factorise());
  return f;
}

// ‖x − A⁻¹b‖ / ‖A⁻¹b‖ within 1e-12 × the condition number's bound (these are well conditioned).
void expect_solves(const Eigen::MatrixXd& a, const BandedLdlt& f) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  const Eigen::VectorXd expected = a.ldlt().solve(b);
  Eigen::VectorXd x = b;
  f.solve_in_place(x);
  EXPECT_LE((x - expected).norm(), 1e-12 * expected.norm());
}

TEST(BandedLdlt, SolvesPositiveDefiniteBandsOfEveryWidth) {
  for (const int n : {1, 2, 7, 40})
    for (const int bandwidth : {0, 1, 2, 5, 8, 60}) {
      SCOPED_TRACE(testing::Message() << "n " << n << ", bandwidth " << bandwidth);
      const Eigen::MatrixXd a = random_band(n, bandwidth, 1.5, static_cast<unsigned>(31 * n + bandwidth));
      expect_solves(a, factorised(a, bandwidth));
    }
}

TEST(BandedLdlt, TakesNegativePivotsAsEigensLdltDoes) {
  Eigen::MatrixXd a = random_band(30, 3, 1.5, 5u);
  a(10, 10) = -a(10, 10);  // one negative eigenvalue or so; no zero leading minor
  expect_solves(a, factorised(a, 3));
}

TEST(BandedLdlt, RefusesAZeroPivot) {
  BandedLdlt f(3, 1);
  f.at(0, 0) = 1.0;
  f.at(1, 0) = 1.0;
  f.at(1, 1) = 1.0;  // the leading 2 × 2 minor is singular
  f.at(2, 2) = 1.0;
  EXPECT_FALSE(f.factorise());
}

TEST(BandedLdlt, RefusesEntriesOutsideTheLowerBandAndMisuse) {
  BandedLdlt f(5, 2);
  EXPECT_THROW(f.at(1, 2), std::out_of_range);  // above the diagonal
  EXPECT_THROW(f.at(4, 1), std::out_of_range);  // below the band
  EXPECT_THROW(f.at(5, 5), std::out_of_range);
  EXPECT_THROW(BandedLdlt(-1, 0), std::invalid_argument);
  EXPECT_THROW(BandedLdlt(3, -1), std::invalid_argument);
  Eigen::VectorXd wrong(4);
  EXPECT_THROW(f.solve_in_place(wrong), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::banded_ldlt_test
