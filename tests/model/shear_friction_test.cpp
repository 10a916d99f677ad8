// Shear friction on four-sided cells: the shear angle read from the diagonals is the cell's
// simple shear and ignores its stretch along warp or weft; force and one node's change agree with
// the energy by central differences; the stiffness is positive semi-definite and differs from
// the energy's Hessian only by the dropped diagonal's negative part.
#include "fabform/model/shear_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include "fabform/model/model.hpp"
#include "support/flat_models.hpp"
#include "support/term_checks.hpp"

namespace fabform::shear_friction_test {
namespace {

Model model_of(const FabricSpec& spec) { return test::free_model(Fabric(spec)); }

// Square cells, oblong ones (2:1) and a jittered circle's.
std::vector<FabricSpec> meshes() {
  FabricSpec jittered{0.3, 0.3, 8, 8, FabricSpec::Shape::circle, FabricSpec::Mesh::jittered};
  jittered.jitter = 0.15;
  return {FabricSpec{0.2, 0.1, 6, 3}, FabricSpec{0.2, 0.1, 4, 8}, jittered};
}

TEST(ShearFriction, NeedsItsLoadingBranchKept) {
  EXPECT_EQ(ShearFriction(1.0, 1e-3).needs(), SolverNeeds(SolverNeed::loading_branch));
}

TEST(ShearFriction, ShearAngleIsTheCellsSimpleShearAndIgnoresItsStretch) {
  const ShearFriction friction(1.0, 1e-3);
  for (const FabricSpec& spec : {FabricSpec{0.2, 0.1, 6, 3}, FabricSpec{0.2, 0.1, 4, 8}}) {
    const Model model = model_of(spec);
    const Positions flat = test::flat_positions(model.fabric);
    const double gamma = 1e-4;
    Positions sheared = flat, stretched = flat;
    for (std::size_t k = 0; k < flat.size(); ++k) {
      sheared[k].x() += gamma * flat[k].y();
      stretched[k].x() *= 1.03, stretched[k].y() *= 0.98;
    }
    for (int f = 0; f < static_cast<int>(model.fabric.faces().size()); ++f) {
      // Diagonal strains carry γ to first order: O(γ²) left, relative.
      EXPECT_NEAR(std::abs(friction.shear_angle(model, f, sheared)), gamma, 1e-3 * gamma) << f;
      EXPECT_NEAR(friction.shear_angle(model, f, stretched), 0.0, 1e-14) << f;
    }
  }
}

// Bent, sheared and stretched at random, far past the rounding and inside it, on each mesh.
TEST(ShearFriction, ForceAndNodeChangesAgreeWithItsEnergy) {
  for (const FabricSpec& spec : meshes()) {
    const Model model = model_of(spec);
    for (const double amplitude : {1e-2, 1e-6}) {
      const ShearFriction friction(1.5, 1.7e-3);
      std::mt19937 rng(11u);
      std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
      Positions x = test::flat_positions(model.fabric);
      for (auto& p : x) p += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
      SCOPED_TRACE(amplitude);
      // Steps small against the cells' distance from the rounding's corner, where ρ'' jumps.
      test::expect_force_is_minus_the_gradient(model, friction, x, 1e-5 * amplitude, 1e-6);
      test::expect_node_changes_are_the_whole(model, friction, x, {0, model.fabric.node_count() / 2},
                                              Eigen::Vector3d(1e-1, -2e-1, 3e-1) * amplitude);
    }
  }
}

// The energy's Hessian by central differences of the force.
Eigen::MatrixXd hessian_by_differences(const Model& model, const Term& term, const Positions& x, double step) {
  const int n = model.node_count();
  Eigen::MatrixXd h(3 * n, 3 * n);
  for (int k = 0; k < n; ++k)
    for (int axis = 0; axis < 3; ++axis) {
      Positions plus = x, minus = x;
      plus[static_cast<std::size_t>(k)][axis] += step, minus[static_cast<std::size_t>(k)][axis] -= step;
      for (int j = 0; j < n; ++j) {
        const auto at = static_cast<std::size_t>(j);
        h.block<3, 1>(3 * j, 3 * k + axis) =
            -(term.force_at(model, plus, j, plus[at]) - term.force_at(model, minus, j, minus[at])) / (2.0 * step);
      }
    }
  return 0.5 * (h + h.transpose());
}

// Positive semi-definite, and what it leaves out (one diagonal's ρ'·∂²ε per cell) is negative
// semi-definite: the stiffness is the Hessian made positive semi-definite, as Newton needs.
TEST(ShearFriction, StiffnessIsTheHessianMadePositiveSemiDefinite) {
  for (const FabricSpec& spec : meshes()) {
    const Model model = model_of(spec);
    const ShearFriction friction(1.5, 1.7e-3);
    for (const double amplitude : {1e-2, 1e-5}) {
      std::mt19937 rng(17u);
      std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
      Positions x = test::flat_positions(model.fabric);
      for (auto& p : x) p += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
      const Eigen::MatrixXd k = test::dense_stiffness(model, friction, x);
      const Eigen::MatrixXd h = hessian_by_differences(model, friction, x, 1e-4 * amplitude);
      const double scale = k.cwiseAbs().maxCoeff();
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> of_k(k), left_out(h - k);
      EXPECT_GT(of_k.eigenvalues().minCoeff(), -1e-9 * scale) << amplitude;
      EXPECT_LT(left_out.eigenvalues().maxCoeff(), 1e-5 * scale) << amplitude;
    }
  }
}

// One cell: moves that carry the left-out diagonal's two ends alike do not see the left-out part,
// and there the stiffness is the Hessian.
TEST(ShearFriction, OnOneCellTheStiffnessIsTheHessianWhereTheLeftOutDiagonalMovesRigidly) {
  const Model model = model_of(FabricSpec{0.01, 0.01, 1, 1});
  const ShearFriction friction(1.5, 1.7e-3);
  Positions x = test::flat_positions(model.fabric);
  for (const double shear : {0.01, -0.01, 1e-4}) {
    Positions s = x;
    for (std::size_t k = 0; k < s.size(); ++k) s[k].x() += shear * x[k].y(), s[k].z() += 1e-3 * x[k].x();
    const double gamma = friction.shear_angle(model, 0, s);
    const Face& face = model.fabric.faces()[0];
    const int left_out_a = gamma >= 0.0 ? face.corner[1] : face.corner[0];  // the left-out diagonal's ends
    const int left_out_b = gamma >= 0.0 ? face.corner[3] : face.corner[2];
    const Eigen::MatrixXd k = test::dense_stiffness(model, friction, s);
    const Eigen::MatrixXd h = hessian_by_differences(model, friction, s, 1e-8);
    std::mt19937 rng(3u);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 5; ++trial) {
      Eigen::VectorXd v(12);
      for (int i = 0; i < 12; ++i) v[i] = normal(rng);
      v.segment<3>(3 * left_out_a) = v.segment<3>(3 * left_out_b);
      EXPECT_NEAR(v.dot(k * v), v.dot(h * v), 1e-5 * k.cwiseAbs().maxCoeff() * v.squaredNorm()) << shear;
    }
  }
}

}  // namespace
}  // namespace fabform::shear_friction_test
