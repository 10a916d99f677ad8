// Bending friction in hinges: a face folded by φ past the rounding stores HB·l·|k| (the work of a
// moment HB per width turned through the fold, |k| = 2·sin(φ/2)); inside the rounding the energy
// is the Huber quadratic and meets the line with its slope; force, one node's change and stiffness
// agree with the energy by central differences, bent and nearly flat; warp and weft each act
// across the sides the hinges bend them at.
#include "fabform/model/hinge_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/model.hpp"
#include "support/flat_models.hpp"
#include "support/term_checks.hpp"

namespace fabform::hinge_friction_test {
namespace {

Model hinged_model(FabricSpec spec) {
  spec.hinges = true;
  return test::free_model(Fabric(spec));
}

TEST(HingeFriction, NeedsItsLoadingBranchKept) {
  EXPECT_EQ(HingeFriction(4e-4, 4e-4, 10.0).needs(), SolverNeeds(SolverNeed::loading_branch));
}

TEST(HingeFriction, FoldPastTheRoundingStoresTheFrictionMomentsWork) {
  const Model model = hinged_model({0.2, 0.1, 6, 3});
  const HingeFriction friction(4e-4, 4e-4, 10.0);
  const Positions flat = test::flat_positions(model.fabric);
  for (const Hinge& h : model.fabric.hinges()) {
    const Eigen::Vector3d origin = flat[h.edge[0]];
    const Eigen::Vector3d axis = (flat[h.edge[1]] - origin).normalized();
    const double rounding = friction.rounding_angle_of(model, h);
    const double hb_l = friction.friction_moment_of(model, h) * flat_side(model, h).norm();
    EXPECT_DOUBLE_EQ(friction.friction_moment_of(model, h), 2e-4);
    for (const double phi : {-2.0, -0.5, 0.5 * rounding, 3.0 * rounding, 1.0}) {
      Positions x = flat;
      const Eigen::AngleAxisd turn(phi, axis);
      for (const int k : h.wing[1]) x[k] = origin + turn * (flat[k] - origin);
      const double norm = 2.0 * std::sin(0.5 * std::abs(phi));
      const double expected = norm < rounding ? hb_l * norm * norm / (2.0 * rounding) : hb_l * (norm - 0.5 * rounding);
      EXPECT_NEAR(friction.friction_energy(model, h, x, -1, Eigen::Vector3d::Zero()), expected, 1e-12 * hb_l) << phi;
    }
  }
}

// The rounding angle is the rounding curvature times l/(2·s): on square cells (s = 1/2) the
// spacing times the curvature.
TEST(HingeFriction, RoundingAngleIsTheRoundingCurvatureAtTheHinge) {
  const Model model = hinged_model({0.2, 0.1, 8, 4});
  const HingeFriction friction(1e-4, 1e-4, 10.0);
  for (const Hinge& h : model.fabric.hinges()) {
    EXPECT_NEAR(h.shape_factor, 0.5, 1e-12);
    EXPECT_NEAR(friction.rounding_angle_of(model, h), 10.0 * 0.025, 1e-12);
  }
}

// A hinge across a weft side bends the fabric along the warp: it takes the warp's 2HB.
TEST(HingeFriction, WarpAndWeftEachBendTheirOwnWay) {
  const Model model = hinged_model({0.2, 0.1, 8, 4});
  const HingeFriction friction(6e-4, 2e-4, 10.0);
  for (const Hinge& h : model.fabric.hinges()) {
    const Eigen::Vector3d side = model.fabric.rest_position(h.edge[1]) - model.fabric.rest_position(h.edge[0]);
    const bool along_weft = std::abs(side.x()) < 1e-12;  // the weft runs along y
    EXPECT_DOUBLE_EQ(friction.friction_moment_of(model, h), along_weft ? 3e-4 : 1e-4);
  }
}

// Bent at random well past the rounding, and nearly flat (inside it), on each mesh.
TEST(HingeFriction, TermAgreesWithItsEnergyByFiniteDifferences) {
  FabricSpec arc{0.3, 0.3, 0, 0, FabricSpec::Shape::circle, FabricSpec::Mesh::arc};
  arc.rings = 4, arc.spokes = 9;
  for (const FabricSpec& spec : {FabricSpec{0.2, 0.1, 6, 3}, FabricSpec{0.3, 0.3, 8, 8, FabricSpec::Shape::circle},
                                 FabricSpec{0.3, 0.3, 8, 8, FabricSpec::Shape::circle, FabricSpec::Mesh::triangular},
                                 arc}) {
    const Model model = hinged_model(spec);
    for (const double amplitude : {1e-2, 1e-5}) {
      const HingeFriction friction(5e-4, 3e-4, 10.0);
      std::mt19937 rng(21u);
      std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
      Positions x = test::flat_positions(model.fabric);
      for (auto& p : x) p += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
      SCOPED_TRACE(amplitude);
      test::expect_force_is_minus_the_gradient(model, friction, x, 1e-3 * amplitude, 1e-6);
      test::expect_node_changes_are_the_whole(model, friction, x, {0, model.fabric.node_count() / 2},
                                              Eigen::Vector3d(1e-1, -2e-1, 3e-1) * amplitude);
      test::expect_stiffness_is_minus_the_force_derivative(model, friction, x, 1e-4 * amplitude, 1e-5);
    }
  }
}

// Dynamic's bound covers the stiffness at any state: per node, at least half the absolute sum of
// each of its rows (as a spring's k is to its block), flat, inside the rounding and bent past it
// (k̂ near the diagonal, where a projection's rows sum highest).
TEST(HingeFriction, BoundCoversTheStiffnessAtAnyState) {
  const Model model = hinged_model({0.2, 0.1, 6, 3});
  const HingeFriction friction(5e-4, 3e-4, 10.0);
  StiffnessBound bound;
  bound.per_node.assign(static_cast<std::size_t>(model.node_count()), 0.0);
  friction.bound_stiffness(model, bound);
  std::mt19937 rng(5u);
  for (const double amplitude : {0.0, 1e-6, 1e-2}) {
    std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
    Positions x = test::flat_positions(model.fabric);
    for (auto& p : x) p += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    const Eigen::MatrixXd k = test::dense_stiffness(model, friction, x);
    for (int row = 0; row < k.rows(); ++row)
      EXPECT_GE(bound.per_node[static_cast<std::size_t>(row / 3)] * (1.0 + 1e-12), 0.5 * k.row(row).cwiseAbs().sum())
          << "row " << row << " amplitude " << amplitude;
  }
}

}  // namespace
}  // namespace fabform::hinge_friction_test
