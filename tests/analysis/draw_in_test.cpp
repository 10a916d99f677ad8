// Draw-in (draw_in.hpp): an edge pulled uniformly inwards by d reads d at every edge node,
// corners included (along their diagonal); pushed outwards, −d; a circle's rim moved towards
// its centre reads the radial move; an interior node has none; moves in z do not count.
#include <gtest/gtest.h>

#include <cmath>

#include "fabform/analysis/draw_in.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::draw_in_test {
namespace {

TEST(DrawIn, AUniformShrinkReadsItsMoveAtEveryEdgeNode) {
  const Model model = test::clamped_fabric(6);
  const Eigen::Vector3d centre(0.05, 0.05, 0.0);
  Positions x = model.start;
  for (auto& p : x) p = centre + 0.9 * (p - centre) + Eigen::Vector3d(0.0, 0.0, 0.01);
  const DrawIn d = draw_in(model, x);
  for (int k = 0; k < model.node_count(); ++k) {
    const double value = d.per_node_m[static_cast<std::size_t>(k)];
    if (!model.fabric.on_perimeter(k)) {
      EXPECT_TRUE(std::isnan(value)) << k;
      continue;
    }
    const bool corner = (model.fabric.i_of(k) % 6 == 0) && (model.fabric.j_of(k) % 6 == 0);
    // A side node moved 0.1 × 5 cm straight in; a corner 0.1 × 5√2 cm along its diagonal.
    EXPECT_NEAR(value, corner ? 0.005 * std::sqrt(2.0) : 0.005, 1e-15) << model.fabric.node_name(k);
  }
  EXPECT_NEAR(d.max_m, 0.005 * std::sqrt(2.0), 1e-15);
  EXPECT_TRUE(model.fabric.on_perimeter(d.max_node));
}

TEST(DrawIn, PushedOutwardsIsNegative) {
  const Model model = test::clamped_fabric(4);
  Positions x = model.start;
  const int edge = model.fabric.node(0, 2);  // on the left side: outwards is −x
  x[static_cast<std::size_t>(edge)].x() -= 0.002;
  const DrawIn d = draw_in(model, x);
  EXPECT_NEAR(d.per_node_m[static_cast<std::size_t>(edge)], -0.002, 1e-16);
  EXPECT_EQ(d.max_m, 0.0);  // every other edge node stayed
}

TEST(DrawIn, ACirclesRimReadsItsRadialMove) {
  FabricSpec spec;
  spec.shape = FabricSpec::Shape::circle;
  spec.mesh = FabricSpec::Mesh::arc;
  spec.width_m = spec.height_m = 0.2;
  spec.rings = 4;
  spec.spokes = 12;
  Fabric fabric(spec);
  std::vector<Eigen::Vector3d> start;
  for (int k = 0; k < fabric.node_count(); ++k) start.push_back(fabric.rest_position(k));
  const Model model{fabric, test::linear_table(100.0), test::linear_table(100.0),
                    std::vector<AxisMask>(start.size(), 0), {}, start};
  const Eigen::Vector3d centre(0.1, 0.1, 0.0);
  Positions x = start;
  for (auto& p : x) p = centre + 0.95 * (p - centre);
  const DrawIn d = draw_in(model, x);
  EXPECT_NEAR(d.max_m, 0.05 * 0.1, 1e-14);
  for (int k = 0; k < model.node_count(); ++k)
    if (fabric.on_perimeter(k)) {
      EXPECT_NEAR(d.per_node_m[static_cast<std::size_t>(k)], 0.005, 1e-14);
    }
}

}  // namespace
}  // namespace fabform::draw_in_test
