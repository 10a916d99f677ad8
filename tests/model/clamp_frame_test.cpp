// The blank holder (clamp_frame.hpp): its force is minus its energy's gradient and its
// stiffness minus its force's derivative (central differences); each node holds 2·μ·N_k with
// the holder's force shared by area, so a frame that slides everywhere resists with 2·μ·F in
// all (Coulomb's law on both faces); it acts in the holder's plane only, and only newton takes it.
#include <gtest/gtest.h>

#include "fabform/model/clamp_frame.hpp"
#include "support/clamped_fabric.hpp"
#include "support/term_checks.hpp"

namespace fabform::clamp_frame_test {
namespace {

constexpr double kCreep_m = 1e-4;
constexpr ClampOptions kHolder{20.0, 0.3, kCreep_m};

struct Frame {
  Model model = test::clamped_fabric(4);
  ClampFrame clamp{model.fabric, perimeter(model.fabric), kHolder, model.start};
  Positions x = model.start;

  static std::vector<int> perimeter(const Fabric& fabric) {
    std::vector<int> nodes;
    for (int k = 0; k < fabric.node_count(); ++k)
      if (fabric.on_perimeter(k)) nodes.push_back(k);
    return nodes;
  }

  // Node 0 slipped 0.4 ε, node 1 3 ε, node 2 along a diagonal 0.9 ε; every node a little in z,
  // which the holder does not resist.
  Frame() {
    x[0] += Eigen::Vector3d(0.4 * kCreep_m, 0.0, 1e-5);
    x[1] += Eigen::Vector3d(0.0, -3.0 * kCreep_m, 0.0);
    x[2] += Eigen::Vector3d(0.9 * kCreep_m, 0.9 * kCreep_m, 0.0) / std::sqrt(2.0);
  }
};

TEST(ClampFrame, ForceIsMinusTheGradientOfItsEnergy) {
  const Frame f;
  test::expect_force_is_minus_the_gradient(f.model, f.clamp, f.x, 1e-9, 1e-5);
}

TEST(ClampFrame, StiffnessIsMinusTheDerivativeOfItsForce) {
  const Frame f;
  test::expect_stiffness_is_minus_the_force_derivative(f.model, f.clamp, f.x, 1e-10, 1e-4);
}

TEST(ClampFrame, NodeChangesAreTheWholeEnergysChange) {
  const Frame f;
  test::expect_node_changes_are_the_whole(f.model, f.clamp, f.x, {0, 1, 2}, Eigen::Vector3d(2e-5, -1e-5, 3e-6));
}

TEST(ClampFrame, EachNodeHoldsTwiceMuTimesItsShareOfTheForce) {
  const Frame f;
  const std::vector<double>& area = f.model.fabric.node_areas();
  double frame_area = 0.0;
  for (const int k : f.clamp.nodes()) frame_area += area[static_cast<std::size_t>(k)];
  // Node 1 slid beyond ε: it is held by 2·μ·N_1 exactly, against its slip, in the plane.
  const Eigen::Vector3d sliding = f.clamp.force_at(f.model, f.x, 1, f.x[1]);
  EXPECT_NEAR(sliding.norm(), 2.0 * 0.3 * 20.0 * area[1] / frame_area, 1e-14);
  EXPECT_GT(sliding.y(), 0.0);
  EXPECT_EQ(sliding.z(), 0.0);
  EXPECT_FALSE(f.clamp.stuck(1, f.x[1]));
  EXPECT_TRUE(f.clamp.stuck(0, f.x[0]));
  // An interior node is not the holder's.
  const int middle = f.model.fabric.node(2, 2);
  EXPECT_EQ(f.clamp.force_at(f.model, f.x, middle, f.x[static_cast<std::size_t>(middle)]), Eigen::Vector3d::Zero());
}

TEST(ClampFrame, AFrameSlidingEverywhereResistsWithTwiceMuF) {
  const Frame f;
  Positions x = f.model.start;
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const int k : f.clamp.nodes()) {
    x[static_cast<std::size_t>(k)] += Eigen::Vector3d(5.0 * kCreep_m, 0.0, 0.0);  // all drawn one way
    total += f.clamp.force_at(f.model, x, k, x[static_cast<std::size_t>(k)]);
  }
  EXPECT_NEAR(total.x(), -2.0 * 0.3 * 20.0, 1e-12);
}

TEST(ClampFrame, OnlyNewtonModelsIt) {
  const Frame f;
  EXPECT_EQ(f.clamp.needs(), SolverNeeds(SolverNeed::stick | SolverNeed::stiff_penalty));
}

TEST(ClampOptions, BadValuesAreNamed) {
  std::string field;
  EXPECT_NE((ClampOptions{-1.0, 0.3, kCreep_m}.invalid_reason(&field)), "");
  EXPECT_EQ(field, "force_N");
  EXPECT_NE((ClampOptions{1.0, -0.1, kCreep_m}.invalid_reason(&field)), "");
  EXPECT_EQ(field, "friction");
  EXPECT_NE((ClampOptions{std::nan(""), 0.3, kCreep_m}.invalid_reason(&field)), "");
  EXPECT_EQ(field, "force_N");
  EXPECT_EQ((ClampOptions{0.0, 0.0, kCreep_m}.invalid_reason()), "");
}

}  // namespace
}  // namespace fabform::clamp_frame_test
