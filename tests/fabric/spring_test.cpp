// One spring: its force is minus the energy gradient, its stiffness the energy Hessian,
// checked by central finite differences over slack, in-table and beyond-table strains.
#include "fabform/fabric/spring.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "fabform/material/material_csv.hpp"
#include "test_paths.hpp"

namespace fabform::spring_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kPi = 3.14159265358979323846;

struct TableCase {
  std::string label;
  TensionTable table;
};

// The swim warp (k₀ = 96.96 N/m) under a compression response; buckling with B chosen so that a
// spring of rest length `rest` buckles at ε_b = −0.2, inside the band sampled below.
TensionTable swim_warp_compressed(Compression mode, double rest) {
  TensionTable table = read_material_table(test::source_path("materials/white-swim-solid_warp.csv"));
  table.set_compression(mode, 0.2 * 96.96 * rest * rest / (kPi * kPi));
  return table;
}

std::vector<TableCase> tables(double rest) {
  return {
      {"swim warp, compression linear", swim_warp_compressed(Compression::linear, rest)},
      {"swim warp, compression buckling", swim_warp_compressed(Compression::buckling, rest)},
      {"denim weft (real)",
       read_material_table(test::source_path("materials/11oz-black-denim_weft.csv"))},
      {"swim warp (real)",
       read_material_table(test::source_path("materials/white-swim-solid_warp.csv"))},
      {"synthetic with compression",
       TensionTable({{-0.2, -6.0}, {0.0, 0.5}, {0.15, 9.0}, {0.4, 12.0}}, "synthetic")},
  };
}

// Strain bands to sample: slack (or compression), inside the table, beyond its last point.
std::vector<std::pair<double, double>> strain_bands(const TensionTable& t) {
  return {{-0.9, -0.01}, {t.min_strain() - 0.5, t.min_strain() - 0.01},
          {0.01, t.max_strain() - 0.01}, {t.max_strain() + 0.01, t.max_strain() + 1.5}};
}

// True when a strain is within `band` of a kink of T (a table point, 0 for a tension-only table,
// the buckling strain): the finite differences would straddle a jump of T' there.
bool near_kink(const TensionTable& t, double rest, double strain, double band) {
  if (t.tension_only() && std::abs(strain) < band) return true;
  const CompressionLaw law = t.compression_law(rest);
  if (law.mode == Compression::buckling &&
      std::abs(strain + law.buckling_tension_N_per_m / law.stiffness_N_per_m) < band)
    return true;
  for (const auto& p : t.points())
    if (std::abs(strain - p.strain) < band) return true;
  return false;
}

Eigen::Vector3d random_unit(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Vector3d v;
  do v = {normal(rng), normal(rng), normal(rng)};
  while (v.norm() < 1e-3);
  return v.normalized();
}

class SpringDerivatives : public ::testing::TestWithParam<double> {};  // rest length

TEST_P(SpringDerivatives, ForceAndStiffnessMatchFiniteDifferences) {
  const double rest = GetParam();
  std::mt19937 rng(20240611u + static_cast<unsigned>(rest * 1e4));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Step scaled to the rest length; strain moves by at most h/L = 1e-6 per step.
  const double h = 1e-6 * rest;
  int checked = 0;
  for (const TableCase& tc : tables(rest)) {
    SCOPED_TRACE(tc.label);
    const TensionTable& table = tc.table;
    const Spring spring{0, 1, rest, 0.37 * rest, SpringKind::warp};
    for (const auto& [lo, hi] : strain_bands(table)) {
      if (lo < -0.95 || hi <= lo) continue;  // a band that would fold the spring through itself
      for (int sample = 0; sample < 60; ++sample) {
        const double strain = lo + (hi - lo) * unit(rng);
        if (near_kink(table, rest, strain, 10 * h / rest)) continue;
        const Eigen::Vector3d xa = rest * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
        const Eigen::Vector3d xb = xa + rest * (1.0 + strain) * random_unit(rng);
        SCOPED_TRACE("strain " + std::to_string(strain));
        // The strain the code sees (rounding only).
        ASSERT_NEAR(spring_strain(xa, xb, rest), strain, 1e-12);

        const Eigen::Vector3d force = spring_force_on_a(xa, xb, spring, table);
        const Eigen::Matrix3d stiffness = spring_stiffness(xa, xb, spring, table);
        Eigen::Vector3d gradient;
        Eigen::Matrix3d jacobian;  // d(−force)/dxa, column by column
        double energy_scale = 0.0;
        for (int k = 0; k < 3; ++k) {
          Eigen::Vector3d xp = xa, xm = xa;
          xp[k] += h;
          xm[k] -= h;
          const double ep = spring_energy(xp, xb, spring, table);
          const double em = spring_energy(xm, xb, spring, table);
          energy_scale = std::max({energy_scale, std::abs(ep), std::abs(em)});
          gradient[k] = (ep - em) / (2 * h);
          jacobian.col(k) = -(spring_force_on_a(xp, xb, spring, table) -
                              spring_force_on_a(xm, xb, spring, table)) / (2 * h);
        }
        // Force scale w·|T|; truncation is O((h/ℓ)²) relative, rounding ≈ ε·|E|/h.
        const double force_scale = spring.width * std::abs(table.tension(strain, rest));
        const double force_tol = 1e-6 * force_scale + 64 * kEps * energy_scale / h + 1e-15;
        EXPECT_LE((force + gradient).norm(), force_tol)
            << "force " << force.transpose() << " vs -grad " << -gradient.transpose();

        // Stiffness scale w·(|T'|/L + |T|/ℓ); rounding of force differences ≈ ε·|f|/h.
        const double length = rest * (1.0 + strain);
        const double k_scale = spring.width * (std::abs(table.slope(strain, rest)) / rest +
                                               std::abs(table.tension(strain, rest)) / length);
        const double k_tol = 1e-6 * k_scale + 64 * kEps * force.norm() / h + 1e-15;
        EXPECT_LE((stiffness - jacobian).cwiseAbs().maxCoeff(), k_tol)
            << "K\n" << stiffness << "\nFD\n" << jacobian;
        EXPECT_LE((stiffness - stiffness.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k_scale);

        // Newton's third law: the force on b is −force; the energy only depends on xb − xa.
        EXPECT_LE((spring_force_on_a(xb, xa, Spring{1, 0, rest, spring.width, SpringKind::warp}, table) + force).norm(),
                  1e-12 * (force.norm() + 1e-300));
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 300);
}

INSTANTIATE_TEST_SUITE_P(RestLengths, SpringDerivatives, ::testing::Values(1e-3, 2.5e-3, 0.1, 1.0));

TEST(Spring, ForceDirectionAndMagnitude) {
  const TensionTable table({{0.0, 0.0}, {0.5, 10.0}}, "linear");  // T = 20 ε
  const Spring spring{0, 1, 0.2, 0.05, SpringKind::weft};
  const Eigen::Vector3d xa(1.0, 2.0, 3.0);
  const Eigen::Vector3d xb = xa + Eigen::Vector3d(0.0, 0.3, 0.0);  // ε = 0.5, T = 10 N/m
  const Eigen::Vector3d f = spring_force_on_a(xa, xb, spring, table);
  // f = w·T along b − a: 0.05·10 = 0.5 N, pulling a towards b. A few roundings of 0.5 N.
  EXPECT_NEAR(f.x(), 0.0, 1e-15);
  EXPECT_NEAR(f.y(), 0.5, 1e-14);
  EXPECT_NEAR(f.z(), 0.0, 1e-15);
  // E = w·L·∫₀^0.5 20ε = 0.05·0.2·2.5 = 0.025 J.
  EXPECT_NEAR(spring_energy(xa, xb, spring, table), 0.025, 1e-15);
  // K = w·T'/L along the spring, w·T/ℓ across: 0.05·20/0.2 = 5, 0.05·10/0.3.
  const Eigen::Matrix3d k = spring_stiffness(xa, xb, spring, table);
  EXPECT_NEAR(k(1, 1), 5.0, 1e-13);
  EXPECT_NEAR(k(0, 0), 0.05 * 10.0 / 0.3, 1e-13);
  EXPECT_NEAR(k(2, 2), 0.05 * 10.0 / 0.3, 1e-13);
  EXPECT_NEAR(k(0, 1), 0.0, 1e-15);
}

TEST(Spring, SlackSpringIsInert) {
  const TensionTable table = read_material_table(test::source_path("materials/ivory-rib-knit_warp.csv"));
  const Spring spring{0, 1, 0.01, 0.01, SpringKind::warp};
  const Eigen::Vector3d xa(0.0, 0.0, 0.0), xb(0.004, -0.003, 0.0);  // ℓ = 0.005: ε = −0.5
  EXPECT_EQ(spring_force_on_a(xa, xb, spring, table), Eigen::Vector3d::Zero());
  EXPECT_EQ(spring_stiffness(xa, xb, spring, table), Eigen::Matrix3d::Zero());
  EXPECT_EQ(spring_energy(xa, xb, spring, table), 0.0);
}

TEST(Spring, CoincidentNodesGiveZeroForceAndNoNaN) {
  for (const double rest : {1e-3, 1.0}) {
    for (const TableCase& tc : tables(rest)) {
      SCOPED_TRACE(tc.label);
      const Spring spring{0, 1, rest, rest, SpringKind::warp};
      for (const Eigen::Vector3d& x : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.3, -1.2, 7.0)}) {
        EXPECT_EQ(spring_force_on_a(x, x, spring, tc.table), Eigen::Vector3d::Zero());
        EXPECT_TRUE(spring_stiffness(x, x, spring, tc.table).allFinite());
        EXPECT_TRUE(std::isfinite(spring_energy(x, x, spring, tc.table)));
        EXPECT_EQ(spring_strain(x, x, rest), -1.0);
      }
    }
  }
}

TEST(Spring, NearlyCoincidentNodesStayFinite) {
  // Compression at ε ≈ −1 with the first segment extended: T = −6 + 32.5·(−0.8) = −32 N/m.
  const TensionTable table({{-0.2, -6.0}, {0.0, 0.5}, {0.15, 9.0}}, "synthetic");
  const Spring spring{0, 1, 1e-3, 1e-3, SpringKind::warp};
  const Eigen::Vector3d xa = Eigen::Vector3d::Zero();  // at the origin, so xa + gap ≠ xa
  // 1e-150 apart: the direction is defined and w·T/ℓ is large (3e148) but finite; the force
  // pushes a away from b (−x). 1e-300 and 1e-320 apart: |d|² underflows, so the nodes may
  // count as coincident; whatever the code decides, nothing may become Inf or NaN.
  for (const double gap : {1e-150, 1e-300, 1e-320}) {
    SCOPED_TRACE(gap);
    const Eigen::Vector3d xb = xa + Eigen::Vector3d(gap, 0.0, 0.0);
    const Eigen::Vector3d f = spring_force_on_a(xa, xb, spring, table);
    EXPECT_TRUE(f.allFinite());
    EXPECT_TRUE(std::isfinite(spring_energy(xa, xb, spring, table)));
    if (gap == 1e-150) {
      // A few roundings of 0.032 N.
      EXPECT_NEAR(f.x(), 1e-3 * (-32.0), 1e-15);
      EXPECT_TRUE(spring_stiffness(xa, xb, spring, table).allFinite());
    }
  }
}

}  // namespace
}  // namespace fabform::spring_test
