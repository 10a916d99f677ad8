// A tool's path (tool_path.hpp): after step k of K the body has moved k/K of the way and
// turned k/K of each angle about the pivot, which stays where it is; step K is the whole path.
#include <gtest/gtest.h>

#include "fabform/geometry/placement.hpp"
#include "fabform/geometry/tool_path.hpp"

namespace fabform::tool_path_test {
namespace {

TEST(ToolPath, AStraightPushAdvancesEvenly) {
  const ToolPath path{Eigen::Vector3d(0.0, 0.0, 0.05), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 10};
  const Eigen::Vector3d p(0.01, -0.02, 0.003);
  for (int step = 0; step <= 10; ++step) {
    EXPECT_TRUE((path.pose(step) * p).isApprox(p + Eigen::Vector3d(0.0, 0.0, 0.005 * step), 1e-15)) << step;
    EXPECT_NEAR(path.translation_at(step).z(), 0.005 * step, 1e-17);
  }
  EXPECT_TRUE(path.pose(0).isApprox(Eigen::Isometry3d::Identity(), 0.0));
}

TEST(ToolPath, ATurnKeepsItsPivotAndTurnsEvenly) {
  const Eigen::Vector3d pivot(0.1, 0.2, 0.3);
  const ToolPath path{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 90.0), pivot, 3};
  EXPECT_TRUE((path.pose(2) * pivot).isApprox(pivot, 1e-15));
  // A point 1 m along x from the pivot, turned 60° about z.
  const Eigen::Vector3d turned = path.pose(2) * (pivot + Eigen::Vector3d::UnitX());
  EXPECT_NEAR((turned - pivot).x(), 0.5, 1e-15);
  EXPECT_NEAR((turned - pivot).y(), std::sqrt(3.0) / 2.0, 1e-15);
  EXPECT_TRUE(path.pose(3).linear().isApprox(rotation_from_degrees(Eigen::Vector3d(0.0, 0.0, 90.0)), 1e-15));
}

TEST(ToolPath, BadPathsAreNamed) {
  std::string field;
  ToolPath path{Eigen::Vector3d(0.0, 0.0, 0.01), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0};
  EXPECT_NE(path.invalid_reason(&field), "");
  EXPECT_EQ(field, "steps");
  path.steps = 4;
  EXPECT_EQ(path.invalid_reason(), "");
  path.translation_m = Eigen::Vector3d::Zero();
  EXPECT_NE(path.invalid_reason(&field), "");  // neither moves nor turns
  EXPECT_EQ(field, "translation_m");
}

}  // namespace
}  // namespace fabform::tool_path_test
