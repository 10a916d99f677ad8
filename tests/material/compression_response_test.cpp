// The compression response of tension-only tables (issue 22, item 2): energy, tension and
// slope derivatives of one another in every regime and at its boundaries, Euler's load and the
// elastica's post-buckling branch, and "none" exactly the table's own slack response.
#include "fabform/material/compression_response.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "fabform/material/material_csv.hpp"
#include "fabform/material/tension_table.hpp"
#include "test_paths.hpp"

namespace fabform::compression_response_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kPi = 3.14159265358979323846;

// The Cusick knit's warp (k₀ = 96.96 N/m) and the ARCSim-corrected rigidity the Cusick scene
// would use with one rigidity, the mean of its two (6.95e-6 N·m), on its 7.5 mm springs: T_b = 1.22 N/m, ε_b = −1.26 %.
constexpr double kStiffness = 96.96;
constexpr double kRigidity = 6.95e-6;
constexpr double kRest = 0.0075;

CompressionLaw law(Compression mode) {
  return {mode, kStiffness, mode == Compression::buckling ? euler_buckling_tension(kRigidity, kRest) : 0.0};
}

double buckling_strain(const CompressionLaw& l) { return -l.buckling_tension_N_per_m / l.stiffness_N_per_m; }

// Strains across every regime: at rest, small, both sides of the buckling strain, deep.
std::vector<double> strains(const CompressionLaw& l) {
  const double eb = buckling_strain(l);
  return {0.0, -1e-4, 0.5 * eb, 0.99 * eb, eb, 1.01 * eb, 2.0 * eb, -0.1, -0.34, -0.6, -0.95};
}

TEST(CompressionResponse, EulerLoad) {
  // π² B / L²: 9.8696 · 6.95e-6 / 5.625e-5 N/m.
  EXPECT_NEAR(euler_buckling_tension(kRigidity, kRest), 1.21944, 1e-5);
  EXPECT_NEAR(euler_buckling_tension(1.0, 2.0), kPi * kPi / 4.0, 4 * kEps);
}

TEST(CompressionResponse, ParsesItsNames) {
  for (const Compression mode : {Compression::none, Compression::linear, Compression::buckling}) {
    Compression parsed = Compression::none;
    ASSERT_TRUE(parse_compression(to_string(mode), &parsed));
    EXPECT_EQ(parsed, mode);
  }
  Compression parsed = Compression::none;
  for (const std::string bad : {"", "Linear", "buckle", " none"}) EXPECT_FALSE(parse_compression(bad, &parsed)) << bad;
}

// Central differences with a step of 1e-7 in strain. One-sided at a kink: the derivative there
// is the branch's on the side of the step (the buckling strain belongs to the linear branch).
// Tolerances: truncation O(h²·|Ψ'''|) is 0 on each (at most quadratic) branch, so what is left is
// rounding, ≈ ε·|Ψ|/h for the tension and ε·|T|/h for the slope, times a margin of 64.
TEST(CompressionResponse, TensionIsTheEnergysDerivativeAndSlopeTheTensions) {
  const double h = 1e-7;
  for (const Compression mode : {Compression::linear, Compression::buckling}) {
    const CompressionLaw l = law(mode);
    for (const double e : strains(l)) {
      SCOPED_TRACE(std::string(to_string(mode)) + " at strain " + std::to_string(e));
      const bool at_kink = mode == Compression::buckling && e == buckling_strain(l);
      // Left of a kink or of zero strain (the law's domain is ε ≤ 0): a one-sided difference.
      const double hi = (e == 0.0 || at_kink) ? e : e + h, lo = e - h;
      const double tension_fd = (l.energy_density(hi) - l.energy_density(lo)) / (hi - lo);
      const double slope_fd = (l.tension(hi) - l.tension(lo)) / (hi - lo);
      const double t_ref = (e == 0.0 || at_kink) ? l.tension(e - 0.5 * h) : l.tension(e);
      const double s_ref = (at_kink) ? l.slope(e - h) : l.slope(e);
      EXPECT_NEAR(tension_fd, t_ref, 64 * kEps * (std::abs(l.energy_density(lo)) + 1e-12) / h + 1e-9 * std::abs(t_ref));
      EXPECT_NEAR(slope_fd, s_ref, 64 * kEps * (std::abs(l.tension(lo)) + 1e-12) / h + 1e-9 * s_ref);
    }
  }
}

// The law is continuous where its regimes meet: the tension and the energy at the buckling strain
// from either side agree to rounding (the slope jumps, from k₀ to T_b / 2).
TEST(CompressionResponse, ContinuousAtTheBucklingStrain) {
  const CompressionLaw l = law(Compression::buckling);
  const double eb = buckling_strain(l), below = std::nextafter(eb, -1.0);
  EXPECT_NEAR(l.tension(eb), -l.buckling_tension_N_per_m, 4 * kEps * l.buckling_tension_N_per_m);
  EXPECT_NEAR(l.tension(below), l.tension(eb), 8 * kEps * l.buckling_tension_N_per_m);
  EXPECT_NEAR(l.energy_density(below), l.energy_density(eb), 8 * kEps * l.energy_density(eb));
  EXPECT_DOUBLE_EQ(l.slope(eb), kStiffness);
  EXPECT_DOUBLE_EQ(l.slope(below), 0.5 * l.buckling_tension_N_per_m);
  EXPECT_EQ(l.tension(0.0), 0.0);
  EXPECT_EQ(l.energy_density(0.0), 0.0);
}

// Timoshenko & Gere §2.7: a pin-ended elastica of modulus k carries P/P_cr = (2K(k)/π)² at an
// end shortening Δ/L = 2 − 2E(k)/K(k). The law's branch past buckling, T_b (1 + Δ/2L), is its
// first order: within 0.5 % of it up to Δ/L = 0.1 and within 3.5 % up to Δ/L = 0.34 (the
// largest compression a tension-only drape showed, issue 22).
TEST(CompressionResponse, PostBucklingBranchFollowsTheElastica) {
  const CompressionLaw l = law(Compression::buckling);
  const double eb = buckling_strain(l), pcr = l.buckling_tension_N_per_m;
  int checked = 0;
  for (double k = 0.02; k < 0.6; k += 0.02) {
    const double big_k = std::comp_ellint_1(k), big_e = std::comp_ellint_2(k);
    const double shortening = 2.0 - 2.0 * big_e / big_k;
    if (shortening > 0.34) break;
    const double exact = std::pow(2.0 * big_k / kPi, 2);
    const double ours = -l.tension(eb - shortening) / pcr;
    SCOPED_TRACE("shortening " + std::to_string(shortening));
    EXPECT_NEAR(ours, exact, (shortening <= 0.1 ? 0.005 : 0.035) * exact);
    EXPECT_LE(ours, exact);  // the first order is below the elastica: the law errs soft
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

// Linear continues the first slope; its energy is the spring's ½ k₀ ε².
TEST(CompressionResponse, LinearIsTheFirstSlopeContinued) {
  const CompressionLaw l = law(Compression::linear);
  for (const double e : {-1e-6, -0.01, -0.5, -1.0}) {
    EXPECT_DOUBLE_EQ(l.tension(e), kStiffness * e);
    EXPECT_DOUBLE_EQ(l.slope(e), kStiffness);
    EXPECT_DOUBLE_EQ(l.energy_density(e), 0.5 * kStiffness * e * e);
  }
}

// A table that starts slack (k₀ = 0) has nothing to continue: zero, and no division by it.
TEST(CompressionResponse, SlackStartGivesNothing) {
  const CompressionLaw l{Compression::buckling, 0.0, 1.0};
  for (const double e : {0.0, -0.1, -0.9}) {
    EXPECT_EQ(l.tension(e), 0.0);
    EXPECT_EQ(l.energy_density(e), 0.0);
    EXPECT_EQ(l.slope(e), 0.0);
  }
}

TensionTable swim_warp() { return read_material_table(test::source_path("materials/white-swim-solid_warp.csv")); }

// "none", the default, is the table's own response, bit for bit, at every strain.
TEST(CompressionResponse, NoneIsTheTableBitForBit) {
  TensionTable plain = swim_warp(), none = swim_warp();
  none.set_compression(Compression::none, kRigidity);
  for (double e = -0.99; e < 2.0; e += 0.0137)
    for (const TensionTable* t : {&plain, &none}) {
      EXPECT_EQ(t->tension(e, kRest), plain.tension(e));
      EXPECT_EQ(t->slope(e, kRest), plain.slope(e));
      EXPECT_EQ(t->energy_density(e, kRest), plain.energy_density(e));
    }
}

// In tension a compression response changes nothing; in compression the table gives the law's,
// with k₀ its first segment's slope (the knit's warp: 1.9392 N/m at 2 %).
TEST(CompressionResponse, TableUsesTheLawOnlyInCompression) {
  TensionTable table = swim_warp();
  const TensionTable plain = swim_warp();
  table.set_compression(Compression::buckling, kRigidity);
  const CompressionLaw l = table.compression_law(kRest);
  EXPECT_DOUBLE_EQ(l.stiffness_N_per_m, 1.9392 / 0.02);
  EXPECT_DOUBLE_EQ(l.buckling_tension_N_per_m, euler_buckling_tension(kRigidity, kRest));
  for (double e = 1e-9; e < 2.0; e += 0.0137) {
    EXPECT_EQ(table.tension(e, kRest), plain.tension(e));
    EXPECT_EQ(table.energy_density(e, kRest), plain.energy_density(e));
  }
  for (const double e : strains(l)) {
    EXPECT_EQ(table.tension(e, kRest), l.tension(e));
    EXPECT_EQ(table.slope(e, kRest), l.slope(e));
    EXPECT_EQ(table.energy_density(e, kRest), l.energy_density(e));
  }
  // A longer spring buckles sooner: T_b falls as 1/L².
  EXPECT_DOUBLE_EQ(table.compression_law(2 * kRest).buckling_tension_N_per_m, 0.25 * l.buckling_tension_N_per_m);
}

// A first segment that falls (fabric.softening) has no stiffness to continue: k₀ = 0, so a
// compressed spring is never pushed apart.
TEST(CompressionResponse, FallingFirstSegmentGivesNothing) {
  TensionTable table({{0.0, 0.0}, {0.1, -0.5}, {0.3, 4.0}}, "dips first");
  table.set_compression(Compression::linear);
  EXPECT_EQ(table.compression_law(kRest).stiffness_N_per_m, 0.0);
  EXPECT_EQ(table.tension(-0.2, kRest), 0.0);
}

// A table that measured compression keeps its measurement whatever the scene asks.
TEST(CompressionResponse, MeasuredCompressionIsKept) {
  const TensionTable plain({{-0.1, -2.0}, {0.1, 3.0}, {0.4, 12.0}}, "with compression");
  TensionTable table = plain;
  table.set_compression(Compression::buckling, kRigidity);
  for (double e = -0.5; e < 0.6; e += 0.01) {
    EXPECT_EQ(table.tension(e, kRest), plain.tension(e));
    EXPECT_EQ(table.slope(e, kRest), plain.slope(e));
    EXPECT_EQ(table.energy_density(e, kRest), plain.energy_density(e));
  }
}

}  // namespace
}  // namespace fabform::compression_response_test
