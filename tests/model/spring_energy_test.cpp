// A spring as an energy element over its six coordinates: the gradient is the energy's
// derivative, the Hessian the gradient's, the projected Hessian is positive semi-definite, and
// summed over a grid −∇Π is the node force the relaxation uses.
#include "fabform/model/spring_energy.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>
#include <random>

#include "fabform/material/material_csv.hpp"
#include "fabform/model/model.hpp"
#include "test_paths.hpp"

namespace fabform::spring_energy_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

std::vector<TensionTable> tables() {
  return {read_material_table(test::source_path("materials/white-swim-solid_warp.csv")),
          TensionTable({{-0.2, -6.0}, {0.0, 0.5}, {0.15, 9.0}, {0.4, 12.0}}, "compression"),
          // A softening segment (T' < 0), as a measured curve past its peak can have.
          TensionTable({{0.0, 0.0}, {0.2, 10.0}, {0.4, 7.0}, {0.6, 12.0}}, "softening")};
}

// Whether the strain is within `band` of a kink of T (a table point, or 0 for a tension-only
// table): there T' jumps and a finite difference straddling it says nothing.
bool near_kink(const TensionTable& t, double strain, double band) {
  if (t.tension_only() && std::abs(strain) < band) return true;
  return std::any_of(t.points().begin(), t.points().end(),
                     [&](const TablePoint& p) { return std::abs(strain - p.strain) < band; });
}

struct Sample {
  Vector6d x;  // xa, xb
  double strain;
};

// Random springs of rest length L at strains from −0.8 (slack or compressed) to 3 (beyond
// every table), in random orientations.
std::vector<Sample> samples(double rest, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), strain(-0.8, 3.0);
  std::normal_distribution<double> normal;
  std::vector<Sample> out;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Vector3d u = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    const Eigen::Vector3d xa = rest * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    const double e = strain(rng);
    Vector6d x;
    x << xa, xa + rest * (1.0 + e) * u;
    out.push_back({x, e});
  }
  return out;
}

const Spring kSpring{0, 1, 2.5e-3, 2.5e-3, SpringKind::warp};

double energy(const Vector6d& x, const TensionTable& t) {
  return spring_energy(x.head<3>(), x.tail<3>(), kSpring, t);
}
Vector6d gradient(const Vector6d& x, const TensionTable& t) {
  return spring_gradient(x.head<3>(), x.tail<3>(), kSpring, t);
}

// Central differences with h = 1e-6·L move the strain by ≤ 1e-6·√2, so samples 1e-5 away from a
// kink see one quadratic piece of the energy: the truncation error is then O(h²) relative
// (the geometry is smooth), below 1e-6 of the scale; rounding adds ε·|E|/h (gradient) and
// ε·|∇E|/h (Hessian), allowed 64 times over.
TEST(SpringEnergy, GradientAndHessianMatchFiniteDifferences) {
  const double h = 1e-6 * kSpring.rest_length;
  int checked = 0;
  for (const TensionTable& table : tables()) {
    SCOPED_TRACE(table.name());
    for (const Sample& s : samples(kSpring.rest_length, 7u)) {
      if (near_kink(table, s.strain, 1e-5)) continue;
      Vector6d fd_gradient;
      Matrix6d fd_hessian;
      for (int i = 0; i < 6; ++i) {
        Vector6d up = s.x, down = s.x;
        up[i] += h, down[i] -= h;
        fd_gradient[i] = (energy(up, table) - energy(down, table)) / (2 * h);
        fd_hessian.col(i) = (gradient(up, table) - gradient(down, table)) / (2 * h);
      }
      const double length = kSpring.rest_length * (1.0 + s.strain);
      const double f_scale = kSpring.width * std::abs(table.tension(s.strain));
      const double k_scale = kSpring.width * (std::abs(table.slope(s.strain)) / kSpring.rest_length +
                                              std::abs(table.tension(s.strain)) / length);
      const double e_abs = std::abs(energy(s.x, table));
      EXPECT_LE((gradient(s.x, table) - fd_gradient).lpNorm<Eigen::Infinity>(),
                1e-6 * f_scale + 64 * kEps * e_abs / h + 1e-15);
      const Matrix6d exact = spring_hessian(s.x.head<3>(), s.x.tail<3>(), kSpring, table);
      EXPECT_LE((exact - fd_hessian).lpNorm<Eigen::Infinity>(),
                1e-6 * k_scale + 64 * kEps * f_scale / h + 1e-15);
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
}

// Eigenvalues of [[K, −K], [−K, K]] are 0 and twice K's; K's are w·T'⁺/L and w·T⁺/l, so the
// smallest may be 0 but, to rounding of the largest, not below.
TEST(SpringEnergy, ProjectedHessianIsPositiveSemiDefinite) {
  int indefinite_exact = 0;
  for (const TensionTable& table : tables()) {
    SCOPED_TRACE(table.name());
    for (const Sample& s : samples(kSpring.rest_length, 11u)) {
      const Eigen::Vector3d xa = s.x.head<3>(), xb = s.x.tail<3>();
      const Matrix6d projected = spring_hessian_from(projected_spring_stiffness(xa, xb, kSpring, table));
      const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(projected);
      const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
      EXPECT_GE(eig.eigenvalues().minCoeff(), -64 * kEps * largest);
      const Eigen::SelfAdjointEigenSolver<Matrix6d> exact(spring_hessian(xa, xb, kSpring, table));
      if (exact.eigenvalues().minCoeff() < -1e-9 * largest) ++indefinite_exact;
      // Where the exact Hessian is already PSD (T ≥ 0, T' ≥ 0) the projection changes nothing.
      if (table.tension(s.strain) >= 0.0 && table.slope(s.strain) >= 0.0) {
        EXPECT_LE((projected - spring_hessian(xa, xb, kSpring, table)).norm(), 1e-12 * largest);
      }
    }
  }
  EXPECT_GT(indefinite_exact, 10) << "the samples should include springs that need projecting";
}

// A slack floor replaces only an axial stiffness the table gives as 0 (slack) or less (softening),
// along the spring; a taut spring's stiffness is the projection's own.
TEST(SpringEnergy, SlackFloorActsAlongASlackSpringOnly) {
  const double floor = 7.0;  // N/m
  int slack = 0;
  for (const TensionTable& table : tables()) {
    SCOPED_TRACE(table.name());
    for (const Sample& s : samples(kSpring.rest_length, 11u)) {
      const Eigen::Vector3d xa = s.x.head<3>(), xb = s.x.tail<3>();
      const Eigen::Matrix3d plain = projected_spring_stiffness(xa, xb, kSpring, table);
      const Eigen::Matrix3d floored = projected_spring_stiffness(xa, xb, kSpring, table, floor);
      const Eigen::Vector3d u = (xb - xa).normalized();
      const double scale = std::max(plain.norm(), floor);
      if (table.slope(s.strain) > 0.0) {
        EXPECT_LE((floored - plain).norm(), 1e-15 * scale);
      } else {
        ++slack;
        EXPECT_NEAR((floored - plain).norm(), floor, 1e-12 * scale);  // u uᵀ has norm 1
        EXPECT_NEAR(u.dot(floored * u) - u.dot(plain * u), floor, 1e-12 * scale);
      }
    }
  }
  EXPECT_GT(slack, 10) << "the samples should include slack springs";
}

// Summing every spring's gradient over a randomly deformed grid gives, at every node, minus
// the force node_force computes spring by spring (the same terms, so to a few roundings).
TEST(SpringEnergy, MinusTotalGradientIsTheNodeForce) {
  Fabric grid({0.1, 0.08, 7, 5});
  const TensionTable table = tables()[0];
  const Model model{grid, table, tables()[1], std::vector<AxisMask>(48, 0), {}, {}};
  std::mt19937 rng(3u);
  std::uniform_real_distribution<double> jitter(-0.008, 0.008);
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < grid.node_count(); ++k)
    x.push_back(1.3 * grid.rest_position(k) + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)));
  std::vector<Eigen::Vector3d> total(x.size(), Eigen::Vector3d::Zero());
  for (const Spring& s : grid.springs()) {
    const auto a = static_cast<std::size_t>(s.a), b = static_cast<std::size_t>(s.b);
    const Vector6d g = spring_gradient(x[a], x[b], s, model.table(s.kind));
    total[a] += g.head<3>(), total[b] += g.tail<3>();
  }
  for (int k = 0; k < grid.node_count(); ++k) {
    const Eigen::Vector3d force = node_force(model, x, k);
    EXPECT_LE((force + total[static_cast<std::size_t>(k)]).norm(), 1e-13 * (1.0 + force.norm())) << k;
  }
}

}  // namespace
}  // namespace fabform::spring_energy_test
