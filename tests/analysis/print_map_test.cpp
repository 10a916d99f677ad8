// The print map's two directions undo each other: a checkerboard pre-distorted through a formed
// fabric and then seen through the same fabric is the checkerboard again, every pixel within
// one pixel of a square of its colour (nearest-pixel sampling both ways: half a pixel each).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fabform/analysis/print_map.hpp"
#include "support/print_round_trip.hpp"

namespace fabform::print_map_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 10 × 10 cm blank drawn in towards its left side and domed: one to one seen from above.
std::vector<Eigen::Vector3d> formed(const Fabric& fabric, std::vector<Eigen::Vector3d>* flat) {
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < fabric.node_count(); ++k) {
    const Eigen::Vector3d p = fabric.rest_position(k) + Eigen::Vector3d(0.2, -0.1, 0.03);  // where a scene lays it
    flat->push_back(p);
    const double u = (p.x() - 0.2) / 0.1, v = (p.y() + 0.1) / 0.1;
    x.emplace_back(0.2 + 0.1 * (u - 0.15 * u * (1.0 - u)), -0.1 + 0.1 * (v + 0.1 * v * (1.0 - v) * (u - 0.5)),
                   0.03 + 0.02 * std::sin(kPi * u) * std::sin(kPi * v));
  }
  return x;
}

TEST(PrintMap, UnformedBlankIsItsOwnDevelopedView) {
  const Fabric fabric({0.1, 0.05, 10, 5});
  std::vector<Eigen::Vector3d> flat;
  for (int k = 0; k < fabric.node_count(); ++k) flat.push_back(fabric.rest_position(k) + Eigen::Vector3d(1.0, 2.0, 3.0));
  const PrintMap map = print_map(fabric, flat, flat);
  for (std::size_t k = 0; k < flat.size(); ++k) EXPECT_LT((map.blank_uv[k] - map.developed_uv[k]).norm(), 1e-12);
  EXPECT_NEAR(map.blank_uv.back().x(), 1.0, 1e-12);
  EXPECT_NEAR(map.blank_uv.back().y(), 1.0, 1e-12);
  const Image design = checkerboard(60, 30, 6);
  EXPECT_EQ(predistort(map, design).rgba, design.rgba);
}

TEST(PrintMap, CheckerboardReturnsWithinOnePixel) {
  const Fabric fabric({0.1, 0.1, 40, 40});
  std::vector<Eigen::Vector3d> flat;
  const std::vector<Eigen::Vector3d> x = formed(fabric, &flat);
  const PrintMap map = print_map(fabric, flat, x);
  const Image design = checkerboard(240, 240, 12);
  const Image print = predistort(map, design);
  const test::RoundTrip trip = test::round_trip(design, formed_view(map, print));
  EXPECT_GT(trip.covered, 0.8 * 240 * 240) << "the formed part covers most of the blank's frame";
  EXPECT_LE(trip.worst_px, 1) << trip.wrong << " pixels off";
  // The print is not the design: forming moves it.
  EXPECT_NE(print.rgba, design.rgba);
}

}  // namespace
}  // namespace fabform::print_map_test
