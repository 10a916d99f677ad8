// TensionTable: piecewise-linear tension against strain, its slope and its energy density.
#include "fabform/material/tension_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fabform/material/material_csv.hpp"
#include "test_paths.hpp"

namespace fabform::tension_table_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Tension-only: slopes 50, 100, 25 N/m (a stiffening then softening fabric).
TensionTable tension_only_table() {
  return TensionTable({{0.0, 0.0}, {0.1, 5.0}, {0.3, 25.0}, {0.5, 30.0}}, "synthetic tension-only");
}

// With compression: slopes 25 and 30 N/m; prestressed (T(0) = 0.5 N/m) at rest length.
TensionTable compression_table() {
  return TensionTable({{-0.1, -2.0}, {0.1, 3.0}, {0.4, 12.0}}, "synthetic with compression");
}

// Independent linear interpolation/extrapolation of a table, written from the spec
// (materials/README.md, "Meaning"): used as the reference.
double reference_tension(const std::vector<TablePoint>& p, double e) {
  const bool tension_only = p.front().strain >= 0.0;
  if (tension_only && e <= 0.0) return 0.0;
  std::size_t k = 0;
  while (k + 2 < p.size() && e >= p[k + 1].strain) ++k;
  const double s = (p[k + 1].tension_N_per_m - p[k].tension_N_per_m) / (p[k + 1].strain - p[k].strain);
  return p[k].tension_N_per_m + s * (e - p[k].strain);
}

// Composite Simpson's rule for ∫_lo^hi T, split at every table point (and at 0): T is linear
// on each piece, so Simpson is exact there and only rounding remains.
double simpson_energy(const TensionTable& table, double strain) {
  std::vector<double> cuts{0.0, strain};
  for (const auto& point : table.points())
    if (point.strain > std::min(0.0, strain) && point.strain < std::max(0.0, strain))
      cuts.push_back(point.strain);
  std::sort(cuts.begin(), cuts.end());
  double integral = 0.0;
  constexpr int kSteps = 200;  // even
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const double lo = cuts[c], hi = cuts[c + 1], h = (hi - lo) / kSteps;
    double sum = table.tension(lo) + table.tension(hi);
    for (int s = 1; s < kSteps; ++s) sum += (s % 2 == 1 ? 4.0 : 2.0) * table.tension(lo + s * h);
    integral += sum * h / 3.0;
  }
  return strain >= 0.0 ? integral : -integral;
}

std::vector<TensionTable> all_tables() {
  std::vector<TensionTable> tables{tension_only_table(), compression_table()};
  for (const char* name : {"white-swim-solid_warp.csv", "ivory-rib-knit_weft.csv",
                           "11oz-black-denim_weft.csv"})
    tables.push_back(read_material_table(test::source_path(std::string("materials/") + name)));
  return tables;
}

// A strain grid over and beyond the table: below the first point, through every segment,
// beyond the last point.
std::vector<double> sweep_strains(const TensionTable& table) {
  std::vector<double> strains;
  const double lo = std::min(table.min_strain(), 0.0) - 0.5;
  const double hi = table.max_strain() + 0.7;
  for (int k = 0; k <= 997; ++k) strains.push_back(lo + (hi - lo) * k / 997.0);
  return strains;
}

TEST(TensionTable, ValuesAtTablePoints) {
  // Exact at a point's own segment start; the last point is reached as the end of the last
  // segment, a + s·(b − a): a few ulps of the value.
  for (const auto& table : all_tables()) {
    SCOPED_TRACE(table.name());
    for (const auto& point : table.points())
      EXPECT_NEAR(table.tension(point.strain), point.tension_N_per_m,
                  8 * kEps * std::abs(point.tension_N_per_m) + 1e-300);
  }
}

TEST(TensionTable, InterpolatesLinearlyBetweenPoints) {
  const TensionTable table = tension_only_table();
  // Midpoints: 2.5, 15, 27.5; a quarter into the second segment: 5 + 100*0.05 = 10.
  // Tolerance: a handful of roundings of values of order 30 N/m.
  const double tol = 1e-13;
  EXPECT_NEAR(table.tension(0.05), 2.5, tol);
  EXPECT_NEAR(table.tension(0.2), 15.0, tol);
  EXPECT_NEAR(table.tension(0.4), 27.5, tol);
  EXPECT_NEAR(table.tension(0.15), 10.0, tol);
  for (const auto& t : all_tables()) {
    SCOPED_TRACE(t.name());
    for (const double e : sweep_strains(t)) {
      const double expected = reference_tension(t.points(), e);
      // Relative to the largest tension reached nearby: the two evaluations round differently.
      EXPECT_NEAR(t.tension(e), expected, 1e-12 * (1.0 + std::abs(expected))) << "strain " << e;
    }
  }
}

TEST(TensionTable, TensionOnlyIsZeroInCompression) {
  const TensionTable table = tension_only_table();
  EXPECT_TRUE(table.tension_only());
  for (const double e : {-1e-12, -0.01, -0.5, -1.0, -10.0, 0.0}) {
    EXPECT_EQ(table.tension(e), 0.0) << e;
    EXPECT_EQ(table.slope(e), 0.0) << e;
    EXPECT_EQ(table.energy_density(e), 0.0) << e;
  }
  // Just above zero the first segment applies (slope 50 N/m).
  EXPECT_NEAR(table.tension(1e-3), 0.05, 1e-15);
  EXPECT_EQ(table.slope(1e-3), 50.0);
}

TEST(TensionTable, NegativeStrainTableExtendsFirstSegment) {
  const TensionTable table = compression_table();
  EXPECT_FALSE(table.tension_only());
  EXPECT_EQ(table.min_strain(), -0.1);
  // First segment: T = -2 + 25 (e + 0.1); prestress at the rest length T(0) = 0.5.
  // Tolerance: a few roundings of values of order 10 N/m.
  const double tol = 1e-13;
  EXPECT_NEAR(table.tension(0.0), 0.5, tol);
  EXPECT_NEAR(table.tension(-0.3), -7.0, tol);
  EXPECT_NEAR(table.tension(-1.1), -27.0, tol);
  EXPECT_EQ(table.slope(-0.3), 25.0);
  EXPECT_EQ(table.slope(-5.0), 25.0);
  EXPECT_TRUE(table.beyond_range(-0.3));
  EXPECT_FALSE(table.beyond_range(-0.05));
}

TEST(TensionTable, ExtendsLastSegmentBeyondRange) {
  const TensionTable table = tension_only_table();
  EXPECT_EQ(table.max_strain(), 0.5);
  EXPECT_FALSE(table.beyond_range(0.5));
  EXPECT_FALSE(table.beyond_range(0.25));
  EXPECT_TRUE(table.beyond_range(0.5 + 1e-12));
  EXPECT_TRUE(table.beyond_range(3.0));
  // Last segment slope 25: T(1.5) = 30 + 25 * 1.0. Tolerance: a few roundings of 55 N/m.
  EXPECT_NEAR(table.tension(1.5), 55.0, 1e-12);
  EXPECT_EQ(table.slope(1.5), 25.0);
  EXPECT_EQ(table.slope(100.0), 25.0);

  const TensionTable denim =
      read_material_table(test::source_path("materials/11oz-black-denim_weft.csv"));
  const auto& p = denim.points();
  const double last_slope = (p.back().tension_N_per_m - p[p.size() - 2].tension_N_per_m) /
                            (p.back().strain - p[p.size() - 2].strain);
  EXPECT_TRUE(denim.beyond_range(1.2));
  // Relative: the slope is recomputed from the same two points, the product rounds twice.
  EXPECT_NEAR(denim.tension(1.2), p.back().tension_N_per_m + 0.2 * last_slope,
              1e-13 * p.back().tension_N_per_m);
}

TEST(TensionTable, SlopeIsTheSegmentSlope) {
  const TensionTable table = tension_only_table();
  // Inside segments (not at the kinks, where the choice of side is a convention).
  // Within 4 ulps: (25 - 5) / (0.3 - 0.1) is 100.00000000000001 in doubles.
  EXPECT_DOUBLE_EQ(table.slope(0.05), 50.0);
  EXPECT_DOUBLE_EQ(table.slope(0.2), 100.0);
  EXPECT_DOUBLE_EQ(table.slope(0.45), 25.0);
  // Against central differences of tension() everywhere away from the kinks: T is linear
  // there, so the difference is exact up to rounding ≈ ε·|T|/h.
  for (const auto& t : all_tables()) {
    SCOPED_TRACE(t.name());
    const double h = 1e-7;
    for (const double e : sweep_strains(t)) {
      bool near_kink = std::abs(e) < 2 * h;  // 0 is a kink of a tension-only table
      for (const auto& point : t.points()) near_kink |= std::abs(e - point.strain) < 2 * h;
      if (near_kink) continue;
      const double fd = (t.tension(e + h) - t.tension(e - h)) / (2 * h);
      const double tol = 16 * kEps * (1.0 + std::abs(t.tension(e))) / h + 1e-9 * std::abs(t.slope(e));
      EXPECT_NEAR(t.slope(e), fd, tol) << "strain " << e;
    }
  }
}

TEST(TensionTable, EnergyDensityIsIntegralOfTension) {
  for (const auto& t : all_tables()) {
    SCOPED_TRACE(t.name());
    for (const double e : sweep_strains(t)) {
      const double reference = simpson_energy(t, e);
      // Relative 1e-9: Simpson is exact on the linear pieces; the rest is rounding. The
      // absolute floor covers strains where the energy crosses zero (compression table).
      EXPECT_NEAR(t.energy_density(e), reference, 1e-9 * std::abs(reference) + 1e-13)
          << "strain " << e;
    }
    EXPECT_EQ(t.energy_density(0.0), 0.0);  // measured from the rest length
  }
  // A closed form for the tension-only table: up to 0.1, 50 e²/2; at 0.3: 0.25 + (5+25)/2*0.2.
  const TensionTable table = tension_only_table();
  EXPECT_NEAR(table.energy_density(0.1), 0.25, 1e-15);
  EXPECT_NEAR(table.energy_density(0.3), 3.25, 1e-14);
  // Compression table: from 0 down to -0.1, ∫ T = -(area of the trapezoid 0.5 .. -2) = 0.075.
  EXPECT_NEAR(compression_table().energy_density(-0.1), 0.075, 1e-15);
}

TEST(TensionTable, EnergyDerivativeIsTension) {
  // E is quadratic inside a segment, so the central difference is exact up to rounding:
  // |error| ≲ a few ε·|E|/h. Points within 2h of a kink (table points, and 0 for a
  // tension-only table) are skipped: E'' jumps there.
  for (const auto& t : all_tables()) {
    SCOPED_TRACE(t.name());
    const double h = 1e-6;
    int checked = 0;
    for (const double e : sweep_strains(t)) {
      bool near_kink = t.tension_only() && std::abs(e) < 2 * h;
      for (const auto& point : t.points()) near_kink |= std::abs(e - point.strain) < 2 * h;
      if (near_kink) continue;
      const double ep = t.energy_density(e + h), em = t.energy_density(e - h);
      const double fd = (ep - em) / (2 * h);
      const double tol = 64 * kEps * std::max(std::abs(ep), std::abs(em)) / h +
                         1e-9 * std::abs(t.tension(e)) + 1e-12;
      EXPECT_NEAR(fd, t.tension(e), tol) << "strain " << e;
      ++checked;
    }
    EXPECT_GT(checked, 900);
  }
}


TEST(TensionTable, KeepsPointsAndName) {
  const TensionTable table = tension_only_table();
  ASSERT_EQ(table.points().size(), 4u);
  EXPECT_EQ(table.points()[2].strain, 0.3);
  EXPECT_EQ(table.points()[2].tension_N_per_m, 25.0);
  EXPECT_EQ(table.name(), "synthetic tension-only");
}

TEST(TensionTable, AcceptsNegativeZeroStart) {
  // The spec compares by value: (0.0, -0) is the point (0, 0).
  const TensionTable table({{-0.0, -0.0}, {0.1, 1.0}});
  EXPECT_TRUE(table.tension_only());
  EXPECT_EQ(table.tension(-0.5), 0.0);
  EXPECT_NEAR(table.tension(0.05), 0.5, 1e-15);
}

struct InvalidCase {
  const char* what;
  std::vector<TablePoint> points;
};

void PrintTo(const InvalidCase& c, std::ostream* os) { *os << c.what; }

class TensionTableInvalid : public ::testing::TestWithParam<InvalidCase> {};

TEST_P(TensionTableInvalid, Throws) {
  EXPECT_THROW(TensionTable(GetParam().points, "bad"), std::invalid_argument) << GetParam().what;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, TensionTableInvalid,
    ::testing::Values(
        InvalidCase{"no points", {}}, InvalidCase{"one point", {{0.0, 0.0}}},
        InvalidCase{"NaN strain", {{0.0, 0.0}, {kNaN, 1.0}}},
        InvalidCase{"NaN tension", {{0.0, 0.0}, {0.1, kNaN}}},
        InvalidCase{"infinite strain", {{0.0, 0.0}, {kInf, 1.0}}},
        InvalidCase{"infinite tension", {{0.0, 0.0}, {0.1, -kInf}}},
        InvalidCase{"NaN first strain", {{kNaN, 0.0}, {0.1, 1.0}}},
        InvalidCase{"-inf first strain", {{-kInf, 0.0}, {0.1, 1.0}}},
        InvalidCase{"equal strains", {{0.0, 0.0}, {0.1, 1.0}, {0.1, 2.0}}},
        InvalidCase{"decreasing strain", {{0.0, 0.0}, {0.2, 1.0}, {0.1, 2.0}}},
        InvalidCase{"decreasing negative", {{-0.1, -1.0}, {-0.2, 1.0}}},
        InvalidCase{"tension-only not at strain 0", {{0.01, 0.0}, {0.1, 1.0}}},
        InvalidCase{"tension-only not at value 0", {{0.0, 0.5}, {0.1, 1.0}}},
        InvalidCase{"tension-only tiny value", {{0.0, 1e-300}, {0.1, 1.0}}}));

}  // namespace
}  // namespace fabform::tension_table_test
