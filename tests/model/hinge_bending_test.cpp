// Hinge bending in Bergou's quadratic form: the weights are the flat points' affine
// dependency on every mesh; one face folded by φ stores the discrete-shell energy
// 2·B·s·(1 − cos φ) exactly; the bend vector is linear with the stencil's weights as its
// derivative; the energy ignores rigid and affine motions, stays bounded with its force where a
// face collapses, and a fabric rolled on a cylinder stores the continuum's B·κ²/2 per area.
#include "fabform/model/hinge_bending.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include <Eigen/Geometry>

#include "fabform/model/model.hpp"
#include "support/flat_models.hpp"
#include "support/term_checks.hpp"

namespace fabform::hinge_bending_test {
namespace {

Fabric hinged(FabricSpec spec) {
  spec.hinges = true;
  return Fabric(spec);
}

// A rectangle, circles of each mesh: four-sided faces, and the arc's centre triangles.
std::vector<Fabric> hinged_fabrics() {
  FabricSpec arc{0.3, 0.3, 0, 0, FabricSpec::Shape::circle, FabricSpec::Mesh::arc};
  arc.rings = 4, arc.spokes = 9;
  return {hinged({0.2, 0.1, 6, 3}), hinged({0.3, 0.3, 8, 8, FabricSpec::Shape::circle}),
          hinged({0.3, 0.3, 8, 8, FabricSpec::Shape::circle, FabricSpec::Mesh::triangular}), hinged(arc)};
}

// Σ w = 0 and Σ w·q = 0 over the flat points, to rounding: weights ~1/h, positions ~0.3 m.
TEST(HingeWeights, AreTheFlatPointsAffineDependency) {
  for (const Fabric& fabric : hinged_fabrics()) {
    ASSERT_FALSE(fabric.hinges().empty());
    const std::vector<Eigen::Vector3d> x = test::flat_positions(fabric);
    for (const Hinge& h : fabric.hinges()) {
      const HingeStencil stencil = hinge_stencil(h);
      double sum = 0.0, scale = 0.0;
      for (int k = 0; k < stencil.count; ++k) sum += stencil.weight[k], scale += std::abs(stencil.weight[k]);
      EXPECT_LT(std::abs(sum), 1e-12 * scale);
      EXPECT_LT(bend_vector(h, x).norm(), 1e-12 * scale * 0.3);
      EXPECT_GT(h.weight[2], 0.0);
      EXPECT_GT(h.weight[3], 0.0);
    }
  }
}

// Fold a hinge's second face (its far nodes) by φ about the edge: E = 2·B·s·(1 − cos φ).
TEST(HingeBending, OneFaceFoldedStoresTheDiscreteShellEnergy) {
  const double rigidity = 6e-5;
  for (const Fabric& fabric : hinged_fabrics()) {
    const std::vector<Eigen::Vector3d> flat = test::flat_positions(fabric);
    for (const Hinge& h : fabric.hinges()) {
      const Eigen::Vector3d origin = flat[h.edge[0]];
      const Eigen::Vector3d axis = (flat[h.edge[1]] - origin).normalized();
      for (const double phi : {-2.5, -0.3, 1e-4, 0.7, 3.0}) {
        std::vector<Eigen::Vector3d> x = flat;
        const Eigen::AngleAxisd turn(phi, axis);
        for (const int k : h.wing[1]) x[k] = origin + turn * (flat[k] - origin);
        const double expected = 2.0 * rigidity * h.shape_factor * (1.0 - std::cos(phi));
        EXPECT_NEAR(hinge_energy(h, rigidity, x), expected, 1e-12 * rigidity * h.shape_factor) << phi;
      }
    }
  }
}

// k is linear in the positions, ∂k/∂x_j = c_j·I: a central difference is exact up to rounding.
TEST(HingeBending, StencilIsTheBendVectorsDerivative) {
  std::mt19937 rng(7u);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (const Fabric& fabric : hinged_fabrics()) {
    std::vector<Eigen::Vector3d> x = test::flat_positions(fabric);
    for (auto& p : x) p += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    for (const Hinge& h : fabric.hinges()) {
      const HingeStencil stencil = hinge_stencil(h);
      for (int k = 0; k < stencil.count; ++k) {
        const int node = stencil.node[k];
        const double step = 1e-3;
        for (int axis = 0; axis < 3; ++axis) {
          Eigen::Vector3d plus = x[node], minus = x[node];
          plus[axis] += step, minus[axis] -= step;
          const Eigen::Vector3d slope = (bend_vector(h, x, node, plus) - bend_vector(h, x, node, minus)) / (2 * step);
          EXPECT_LT((slope - stencil.weight[k] * Eigen::Vector3d::Unit(axis)).norm(), 1e-9 * std::abs(h.weight[2]))
              << "node " << node << " axis " << axis;
        }
      }
    }
  }
}

// Turned, moved, scaled or sheared in its plane, a flat fabric stores no bending energy, and a
// bent one keeps its energy under rigid motion.
TEST(HingeBending, RigidAndAffineMotionsStoreNothingMore) {
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::Matrix3d affine = turn;
  affine(0, 1) += 0.3, affine(1, 1) *= 0.8;
  std::mt19937 rng(3u);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  for (const Fabric& fabric : hinged_fabrics()) {
    const std::vector<Eigen::Vector3d> flat = test::flat_positions(fabric);
    std::vector<Eigen::Vector3d> sheared, bent = flat, bent_turned;
    for (auto& p : bent) p.z() += jitter(rng);
    for (std::size_t k = 0; k < flat.size(); ++k) {
      sheared.push_back(affine * flat[k] + Eigen::Vector3d(5, -2, 7));
      bent_turned.push_back(turn * bent[k] + Eigen::Vector3d(5, -2, 7));
    }
    for (const Hinge& h : fabric.hinges()) {
      const double scale = 1e-4 * h.shape_factor * h.weight[2] * h.weight[2];  // B·s·(1/h)²
      EXPECT_LT(hinge_energy(h, 1e-4, sheared), 1e-20 * scale * 100.0);
      EXPECT_NEAR(hinge_energy(h, 1e-4, bent_turned), hinge_energy(h, 1e-4, bent), 1e-12 * scale);
    }
  }
}

// A face crushed onto its edge: the dihedral angle would turn infinitely fast there; the
// quadratic energy and force stay finite and small.
TEST(HingeBending, CollapsedFaceKeepsForcesBounded) {
  Model model{hinged({0.1, 0.1, 2, 2}), TensionTable({{0, 0}, {1, 500}}, "t"), TensionTable({{0, 0}, {1, 500}}, "t"),
              std::vector<AxisMask>(9, 0), {}, {}};
  const HingeBending hinges(6e-5);
  std::vector<Eigen::Vector3d> x = test::flat_positions(model.fabric);
  for (auto& p : x)
    if (p.y() > 0.06) p.y() = 0.05 + 1e-13, p.z() = 1e-14;  // the top row onto the middle row
  for (int k = 0; k < model.node_count(); ++k) {
    const Eigen::Vector3d f = hinges.force_at(model, x, k, x[k]);
    ASSERT_TRUE(f.allFinite());
    EXPECT_LT(f.norm(), 1e-2) << k;  // B/h² · h ~ 1e-3 N
  }
  EXPECT_TRUE(std::isfinite(hinges.energy(model, x)));
}

// A 0.2 × 0.1 m fabric rolled round a cylinder of radius R with its axis along y: curvature
// 1/R across the warp, none along the weft. The hinges across weft sides carry B·κ²/2 per area
// over all but one column of cells (the fabric's edges bend nothing). Nodes h apart on the
// circle turn by θ = h/R at each hinge; both far points move off the edge's tangent plane by
// R·(1 − cos θ), so |k| = (2/h)·R·(1 − cos θ) = 4·sin²(θ/2)/θ, and |k|² = θ²·(1 − θ²/6 + …).
TEST(HingeBending, CylinderStoresHalfBKappaSquaredPerArea) {
  const double width = 0.2, height = 0.1, radius = 0.05, rigidity = 7e-5;
  for (const int n : {20, 40, 80}) {
    const Fabric fabric = hinged({width, height, n, n / 2});
    std::vector<Eigen::Vector3d> x;
    for (int k = 0; k < fabric.node_count(); ++k) {
      const Eigen::Vector3d p = fabric.rest_position(k);
      const double angle = p.x() / radius;
      x.emplace_back(radius * std::sin(angle), p.y(), radius * (1.0 - std::cos(angle)));
    }
    double energy = 0.0;
    for (const Hinge& h : fabric.hinges()) energy += hinge_energy(h, rigidity, x);
    const double continuum = 0.5 * rigidity * width * height / (radius * radius);
    const double theta = width / n / radius;
    const double k = 4.0 * std::pow(std::sin(0.5 * theta), 2) / theta;
    EXPECT_NEAR(energy / continuum, (1.0 - 1.0 / n) * k * k / (theta * theta), 1e-12) << n;
  }
}

// The hinges as a term: force, one node's change and stiffness (exact and constant) against
// its energy, by central differences, on every hinged fabric bent at random.
TEST(HingeBending, TermAgreesWithItsEnergyByFiniteDifferences) {
  const HingeBending hinges(5.56e-5);
  for (const Fabric& fabric : hinged_fabrics()) {
    const Model model = test::free_model(fabric);
    std::mt19937 rng(21u);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    Positions x = test::flat_positions(fabric);
    for (auto& p : x) p += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    test::expect_force_is_minus_the_gradient(model, hinges, x, 1e-6, 1e-6);
    test::expect_node_changes_are_the_whole(model, hinges, x, {0, fabric.node_count() / 2},
                                            Eigen::Vector3d(1e-3, -2e-3, 3e-3));
    test::expect_stiffness_is_minus_the_force_derivative(model, hinges, x, 1e-6, 1e-8);
  }
}

}  // namespace
}  // namespace fabform::hinge_bending_test
