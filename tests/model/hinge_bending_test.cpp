// Discrete-shell hinges: the dihedral angle against folds of known angle, its gradient against
// central differences, its invariance under rigid motion, and the energy of a fabric rolled on a
// cylinder against the continuum's B·κ²/2 per area.
#include "fabform/model/hinge_bending.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

namespace fabform {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Edge along x from the origin; face 1's far point at +y, face 2's folded by φ about the edge
// from -y (φ = 0: flat).
std::array<Eigen::Vector3d, 4> folded(double phi, double h1 = 0.7, double h2 = 1.3) {
  return {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.3, h1, 0),
          Eigen::Vector3d(0.6, -h2 * std::cos(phi), h2 * std::sin(phi))};
}

TEST(DihedralAngle, IsTheFoldAngle) {
  EXPECT_EQ(dihedral_angle(folded(0.0)), 0.0);
  const double sign = dihedral_angle(folded(0.5)) > 0 ? 1.0 : -1.0;
  for (const double phi : {-3.0, -2.0, -1.0, -0.25, 1e-6, 0.25, 1.0, 2.0, 3.0})
    EXPECT_NEAR(dihedral_angle(folded(phi)), sign * phi, 1e-14) << phi;
}

TEST(DihedralAngle, CollapsedFaceHasNoAngle) {
  std::array<Eigen::Vector3d, 4> p = folded(0.5);
  p[2] = Eigen::Vector3d(0.4, 0, 0);  // on the edge's line
  EXPECT_EQ(dihedral_angle(p), 0.0);
  for (const auto& g : dihedral_angle_gradient(p)) EXPECT_EQ(g.norm(), 0.0);
}

TEST(DihedralAngle, RigidMotionKeepsIt) {
  const std::array<Eigen::Vector3d, 4> p = folded(0.8);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::array<Eigen::Vector3d, 4> q;
  for (int k = 0; k < 4; ++k) q[k] = turn * p[k] + Eigen::Vector3d(5, -2, 7);
  EXPECT_NEAR(dihedral_angle(q), dihedral_angle(p), 1e-14);
}

// h = 1e-6: truncation ~h²·θ''' ~1e-12, rounding ~ε/h ~1e-10; tolerance 1e-8 of the gradient.
TEST(DihedralAngle, GradientIsItsDerivative) {
  std::mt19937 rng(5u);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    std::array<Eigen::Vector3d, 4> p = folded(-2.5 + 0.25 * trial);
    for (auto& point : p) point += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    const std::array<Eigen::Vector3d, 4> g = dihedral_angle_gradient(p);
    double scale = 0.0;
    for (const auto& v : g) scale = std::max(scale, v.norm());
    for (int k = 0; k < 4; ++k)
      for (int axis = 0; axis < 3; ++axis) {
        const double h = 1e-6;
        std::array<Eigen::Vector3d, 4> plus = p, minus = p;
        plus[k][axis] += h, minus[k][axis] -= h;
        const double slope = (dihedral_angle(plus) - dihedral_angle(minus)) / (2 * h);
        EXPECT_NEAR(g[k][axis], slope, 1e-8 * scale) << "trial " << trial << " point " << k << " axis " << axis;
      }
  }
}

// A 0.2 × 0.1 m fabric rolled round a cylinder of radius R with its axis along y: curvature
// 1/R across the warp, none along the weft. The hinges across weft sides carry B·κ²/2 per area
// over all but one column of cells (the fabric's edges bend nothing). Nodes h apart on the
// circle turn by θ = h/R at each hinge, and 4·sin²(θ/2) = θ²·(1 − θ²/12 + …) stands for θ².
TEST(HingeBending, CylinderStoresHalfBKappaSquaredPerArea) {
  const double width = 0.2, height = 0.1, radius = 0.05, rigidity = 7e-5;
  for (const int n : {20, 40, 80}) {
    FabricSpec spec{width, height, n, n / 2};
    spec.hinges = true;
    const Fabric fabric(spec);
    std::vector<Eigen::Vector3d> x;
    for (int k = 0; k < fabric.node_count(); ++k) {
      const Eigen::Vector3d p = fabric.rest_position(k);
      const double angle = p.x() / radius;
      x.emplace_back(radius * std::sin(angle), p.y(), radius * (1.0 - std::cos(angle)));
    }
    double energy = 0.0;
    for (const Hinge& h : fabric.hinges()) energy += hinge_energy(h, rigidity, x);
    const double continuum = 0.5 * rigidity * width * height / (radius * radius);
    const double h = width / n;
    const double theta = h / radius;
    EXPECT_NEAR(energy / continuum, (1.0 - 1.0 / n) * (1.0 - theta * theta / 12.0), 1e-2 * std::pow(theta, 4)) << n;
  }
}

TEST(HingeBending, FlatFabricStoresNothing) {
  FabricSpec spec{0.3, 0.3, 0, 0};
  spec.shape = FabricSpec::Shape::circle, spec.mesh = FabricSpec::Mesh::arc, spec.rings = 5, spec.spokes = 12;
  spec.hinges = true;
  const Fabric fabric(spec);
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < fabric.node_count(); ++k) x.push_back(fabric.rest_position(k) * 1.1);
  ASSERT_FALSE(fabric.hinges().empty());
  for (const Hinge& h : fabric.hinges()) EXPECT_EQ(hinge_energy(h, 1e-4, x), 0.0);
}

}  // namespace
}  // namespace fabform
