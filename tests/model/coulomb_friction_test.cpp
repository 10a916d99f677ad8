// The smoothed Coulomb friction potential (coulomb_friction.hpp) as every term is checked: its force
// is minus its energy's gradient and its stiffness minus its force's derivative, by central
// differences, on nodes stuck (slip below the creep length ε) and sliding (beyond it); its force
// is bounded by μλ and its stiffness positive semi-definite.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "fabform/model/coulomb_friction.hpp"
#include "support/clamped_fabric.hpp"
#include "support/term_checks.hpp"

namespace fabform::coulomb_friction_test {
namespace {

constexpr double kCreep_m = 1e-4;

// Three nodes of a small grid on tilted planes: node 0 slipped 0.3 ε, node 1 2.5 ε, node 2 not at all.
struct Patch {
  Model model = test::clamped_fabric(2);
  Positions x = model.start;
  CoulombFriction friction{contacts(), kCreep_m, model.node_count()};

  static std::vector<FrictionContact> contacts() {
    const Eigen::Vector3d n0 = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
    const Eigen::Vector3d n1 = Eigen::Vector3d(-0.5, 0.1, 1.0).normalized();
    return {{0, 0.02, n0, Eigen::Vector3d(0.001, 0.002, 0.0)},
            {1, 0.05, n1, Eigen::Vector3d(0.05, 0.0, 0.0)},
            {2, 0.01, Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0.1, 0.0, 0.0)}};
  }

  Patch() {
    const auto tangent = [](const Eigen::Vector3d& n) { return n.cross(Eigen::Vector3d::UnitX()).normalized(); };
    const auto c = contacts();
    x[0] = c[0].anchor + 0.3 * kCreep_m * tangent(c[0].normal) + 1e-5 * c[0].normal;
    x[1] = c[1].anchor + 2.5 * kCreep_m * tangent(c[1].normal) - 2e-5 * c[1].normal;
    x[2] = c[2].anchor;
  }
};

TEST(CoulombFriction, ForceIsMinusTheGradientOfItsEnergy) {
  const Patch p;
  test::expect_force_is_minus_the_gradient(p.model, p.friction, p.x, 1e-8, 1e-6);
}

TEST(CoulombFriction, StiffnessIsMinusTheDerivativeOfItsForce) {
  const Patch p;
  test::expect_stiffness_is_minus_the_force_derivative(p.model, p.friction, p.x, 1e-9, 1e-5);
}

TEST(CoulombFriction, NodeChangesAreTheWholeEnergysChange) {
  const Patch p;
  test::expect_node_changes_are_the_whole(p.model, p.friction, p.x, {0, 1}, Eigen::Vector3d(3e-5, -1e-5, 2e-6));
}

TEST(CoulombFriction, StuckNodeIsHeldBySpringSlidingNodeByMuLambda) {
  const Patch p;
  // Beyond ε the force is μλ against the slip; below, it grows as f1(y) = 2y/ε − y²/ε².
  EXPECT_NEAR(p.friction.force_at(p.model, p.x, 1, p.x[1]).norm(), 0.05, 1e-15);
  EXPECT_NEAR(p.friction.force_at(p.model, p.x, 0, p.x[0]).norm(), 0.02 * (0.6 - 0.09), 1e-15);
  EXPECT_EQ(p.friction.force_at(p.model, p.x, 2, p.x[2]), Eigen::Vector3d::Zero());
  EXPECT_EQ(p.friction.force_at(p.model, p.x, 3, p.x[3]), Eigen::Vector3d::Zero());  // not on a body
  // The force lies in the plane across the body's normal.
  EXPECT_NEAR(p.friction.force_at(p.model, p.x, 0, p.x[0]).dot(Patch::contacts()[0].normal), 0.0, 1e-17);
}

TEST(CoulombFriction, EnergyIsContinuousAtTheCreepLength) {
  const Patch p;
  const FrictionContact c = Patch::contacts()[2];
  Positions below = p.x, above = p.x;
  below[2] = c.anchor + Eigen::Vector3d(kCreep_m * (1.0 - 1e-9), 0.0, 0.0);
  above[2] = c.anchor + Eigen::Vector3d(kCreep_m * (1.0 + 1e-9), 0.0, 0.0);
  const double jump = p.friction.energy(p.model, above) - p.friction.energy(p.model, below);
  EXPECT_NEAR(jump, 0.01 * 2e-9 * kCreep_m, 1e-9 * 0.01 * kCreep_m);
}

TEST(CoulombFriction, StiffnessIsPositiveSemiDefinite) {
  const Patch p;
  for (const double slip : {0.0, 0.5, 0.999, 1.0, 3.0}) {
    Positions x = p.x;
    x[2] = Patch::contacts()[2].anchor + Eigen::Vector3d(slip * kCreep_m, 0.0, 0.0);
    const Eigen::MatrixXd k = test::dense_stiffness(p.model, p.friction, x);
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues().minCoeff();
    EXPECT_GE(smallest, -1e-12 * k.cwiseAbs().maxCoeff()) << "slip " << slip << " creep lengths";
  }
}

TEST(CoulombFriction, CreepIsAFractionOfTheMeanSpringLength) {
  const Model model = test::clamped_fabric(4);  // 10 cm in 4: warp and weft springs of 2.5 cm
  EXPECT_NEAR(friction_creep_m(model.fabric, 1e-3), 2.5e-5, 1e-18);
}

}  // namespace
}  // namespace fabform::coulomb_friction_test
