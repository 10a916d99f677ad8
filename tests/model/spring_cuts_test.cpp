// Springs cutting into a body (spring_cuts.hpp), against geometry known by hand: a 1 cm cube's
// top edge under a strip whose middle spring spans it. Lowered by d below the edge's height,
// the spring reaches d into the cube at the corner; within 1 % of its length it is a chord,
// not a cut; above the cube nothing cuts; and a spring lying on a sphere's surface between two
// nodes on it sinks only by its sagitta and does not count.
#include <gtest/gtest.h>

#include "fabform/model/spring_cuts.hpp"
#include "support/clamped_fabric.hpp"
#include "support/shapes.hpp"

namespace fabform::spring_cuts_test {
namespace {

// A strip of 4 springs, 1 cm each, along x at height z; the cube [0.015, 0.025]³ + (0, -0.02, -0.02)
// has its top at z = 0.005 and its edge at x = 0.015 under the strip's middle spring (x 0.01…0.02).
Model strip_over_cube(double z) {
  Fabric strip({0.04, 0.005, 4, 1});
  std::vector<Eigen::Vector3d> start;
  for (int k = 0; k < strip.node_count(); ++k) start.push_back(strip.rest_position(k) + Eigen::Vector3d(0.0, 0.0, z));
  std::vector<RigidBody> bodies;
  bodies.emplace_back("cube", test::cube(Eigen::Vector3d(0.015, -0.0025, -0.005), 0.01));
  return Model{strip, test::linear_table(100.0), test::linear_table(100.0),
               std::vector<AxisMask>(start.size(), 0), std::move(bodies), start};
}

TEST(SpringCuts, ASpringBelowAnEdgeReachesInByItsDrop) {
  for (const double drop : {0.0005, 0.001, 0.003}) {
    const Model model = strip_over_cube(0.005 - drop);
    // The node at x = 0.02 is inside the cube too: put it back on the top face, so the cut is
    // the spring from x = 0.01 (outside, below the top) to x = 0.02 (on the top).
    std::vector<Eigen::Vector3d> x = model.start;
    for (int k = 0; k < model.node_count(); ++k)
      if (model.fabric.i_of(k) >= 2) x[static_cast<std::size_t>(k)].z() = 0.005;
    const SpringCuts cuts = find_spring_cuts(model, x);
    // Each of the strip's two rows has one spring over the edge. A point u past the side face
    // (x = 0.015) lies u inside it and drop·(0.5 − u/L) under the top face, L = 1 cm: the
    // deepest, where the two are equal, is 0.5·drop / (1 + drop/L).
    ASSERT_EQ(cuts.springs, 2) << drop;
    EXPECT_NEAR(cuts.deepest_m, 0.5 * drop / (1.0 + drop / 0.01), 1e-6 * drop) << drop;
    const Spring& deepest = model.fabric.springs()[static_cast<std::size_t>(cuts.deepest_spring)];
    EXPECT_EQ(model.fabric.i_of(deepest.a), 1);
  }
}

TEST(SpringCuts, ClearOfTheBodyNothingCuts) {
  const Model model = strip_over_cube(0.006);
  const SpringCuts cuts = find_spring_cuts(model, model.start);
  EXPECT_EQ(cuts.springs, 0);
  EXPECT_EQ(cuts.deepest_m, 0.0);
  EXPECT_EQ(cuts.deepest_spring, -1);
}

// Two nodes on a sphere of radius 2 cm, 1 cm apart: the chord sinks L/(8R) = 6 % of its length
// into it, a cut; 1 mm apart, 0.6 %, a chord. (Both rows of the pair lie at y = 0.)
TEST(SpringCuts, AChordOfACurveIsACutOnlyWhenTheCurveIsSharpForTheMesh) {
  for (const auto& [length, cuts_expected] : {std::pair<double, int>{0.01, 2}, {0.001, 0}}) {
    Fabric pair({length, 0.001, 1, 1});
    std::vector<Eigen::Vector3d> x;
    const double r = 0.02, half = 0.5 * length / r;  // half the angle the chord spans
    for (int k = 0; k < pair.node_count(); ++k) {
      const double side = pair.i_of(k) == 0 ? -1.0 : 1.0;
      x.emplace_back(r * std::sin(side * half), 0.0, r * std::cos(half));
    }
    std::vector<RigidBody> bodies;
    bodies.emplace_back("sphere", test::uv_sphere(Eigen::Vector3d::Zero(), r, 180, 360));
    const Model model{pair, test::linear_table(100.0), test::linear_table(100.0),
                      std::vector<AxisMask>(x.size(), 0), std::move(bodies), x};
    EXPECT_EQ(find_spring_cuts(model, x).springs, cuts_expected) << length;
  }
}

}  // namespace
}  // namespace fabform::spring_cuts_test
