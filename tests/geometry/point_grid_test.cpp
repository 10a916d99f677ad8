// PointGrid against brute force: every point within the cell size of a query is found, over
// random clouds at several scales and degenerate ones (empty, coincident, far off, not finite).
#include "fabform/geometry/point_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace fabform::point_grid_test {
namespace {

std::vector<int> brute_force_within(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& q,
                                    double radius) {
  std::vector<int> within;
  for (std::size_t i = 0; i < points.size(); ++i)
    if ((points[i] - q).norm() <= radius) within.push_back(static_cast<int>(i));
  return within;
}

// `near` may return more than the points within the cell; it must hold all of them, ascending.
void expect_holds_all_within(const PointGrid& grid, const std::vector<Eigen::Vector3d>& points,
                             const Eigen::Vector3d& q, double cell) {
  const std::vector<int> near = grid.near(q);
  EXPECT_TRUE(std::is_sorted(near.begin(), near.end()));
  for (const int i : brute_force_within(points, q, cell))
    EXPECT_TRUE(std::binary_search(near.begin(), near.end(), i)) << "point " << i << " missed";
}

TEST(PointGrid, FindsEveryPointWithinTheCellAsBruteForceDoes) {
  std::mt19937 random(7);
  for (const double scale : {1e-3, 1.0, 1e3}) {
    std::uniform_real_distribution<double> coordinate(-scale, scale);
    std::vector<Eigen::Vector3d> points(2000);
    for (auto& p : points) p = {coordinate(random), coordinate(random), coordinate(random)};
    const double cell = 0.1 * scale;
    const PointGrid grid(points, cell);
    for (int t = 0; t < 300; ++t) {
      const Eigen::Vector3d q(coordinate(random), coordinate(random), coordinate(random));
      expect_holds_all_within(grid, points, q, cell);
    }
    // Queries on the points themselves and exactly a cell away along an axis.
    for (int i = 0; i < 50; ++i) {
      expect_holds_all_within(grid, points, points[static_cast<std::size_t>(i)], cell);
      expect_holds_all_within(grid, points, points[static_cast<std::size_t>(i)] + Eigen::Vector3d(cell, 0, 0), cell);
    }
  }
}

TEST(PointGrid, ReturnsFewCandidatesWhereThePointsAreSpread) {
  // A 100 x 100 sheet of spacing 1 binned by 1.5: the 3 x 3 cubes around a point span 4.5, so
  // they hold at most 5 x 5 of its 10^4 points.
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) points.emplace_back(i, j, 0.0);
  const PointGrid grid(points, 1.5);
  EXPECT_LE(grid.near({50.2, 50.2, 0.0}).size(), 25u);
}

TEST(PointGrid, DegenerateClouds) {
  const std::vector<Eigen::Vector3d> none;
  EXPECT_TRUE(PointGrid(none, 1.0).near(Eigen::Vector3d::Zero()).empty());

  const std::vector<Eigen::Vector3d> same(5, Eigen::Vector3d(0.3, 0.3, 0.3));
  EXPECT_EQ(PointGrid(same, 1e-9).near({0.3, 0.3, 0.3}), (std::vector<int>{0, 1, 2, 3, 4}));

  // A cell that is zero, negative or not finite is taken as 1.
  for (const double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    const PointGrid grid(same, bad);
    EXPECT_EQ(grid.near({0.9, 0.9, 0.9}).size(), 5u) << bad;
  }

  // Far off (cube coordinates clamped) and not finite: no overflow, and the far one still found.
  const std::vector<Eigen::Vector3d> odd{{1e300, 0, 0}, {std::nan(""), 0, 0}, {0, 0, 0}};
  const PointGrid grid(odd, 1e-6);
  EXPECT_EQ(grid.near({1e300, 0, 0}), (std::vector<int>{0}));
  const std::vector<int> at_origin = grid.near(Eigen::Vector3d::Zero());
  EXPECT_TRUE(std::find(at_origin.begin(), at_origin.end(), 2) != at_origin.end());
}

}  // namespace
}  // namespace fabform::point_grid_test
