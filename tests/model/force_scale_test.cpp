// The force scale (force_scale.hpp): a spring's w·dT/dε at rest, the least over warp and weft.
// On a 10 cm grid of 4 × 8 divisions the weft springs stand for 2.5 cm of fabric and the warp
// springs for 1.25 cm (edge springs for half that); with tables of 500 and 300 N/m the least is
// an edge warp spring's 0.625 cm × 500 N/m. A table whose first segment is flat has no scale.
#include <gtest/gtest.h>

#include "fabform/model/force_scale.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::force_scale_test {
namespace {

Model grid_of(const TensionTable& warp, const TensionTable& weft) {
  Fabric grid({0.1, 0.1, 4, 8});
  std::vector<Eigen::Vector3d> start;
  for (int k = 0; k < grid.node_count(); ++k) start.push_back(grid.rest_position(k));
  return Model{grid, warp, weft, std::vector<AxisMask>(start.size(), 0), {}, start};
}

TEST(ForceScale, IsTheLeastSpringsWidthTimesItsInitialStiffness) {
  const Model model = grid_of(test::linear_table(500.0), test::linear_table(300.0));
  double least = 1e300;
  for (const Spring& s : model.fabric.springs())
    least = std::min(least, s.width * (s.kind == SpringKind::warp ? 500.0 : 300.0));
  EXPECT_NEAR(spring_force_scale_N(model), least, 1e-15);
  EXPECT_NEAR(least, std::min(0.5 * 0.0125 * 500.0, 0.5 * 0.025 * 300.0), 1e-15);
}

// The stiffness is the first segment's above zero strain, not the slack side's (0) nor a later one.
TEST(ForceScale, TakesTheSegmentJustAboveZeroStrain) {
  const TensionTable knit({{0.0, 0.0}, {0.1, 2.0}, {0.5, 80.0}}, "knit");
  const Model model = grid_of(knit, knit);
  EXPECT_NEAR(spring_force_scale_N(model), 0.5 * 0.0125 * 20.0, 1e-15);
}

TEST(ForceScale, ATableThatStartsFlatHasNone) {
  const TensionTable slack({{0.0, 0.0}, {0.05, 0.0}, {0.5, 80.0}}, "slack");
  EXPECT_EQ(spring_force_scale_N(grid_of(slack, test::linear_table(100.0))), 0.0);
}

}  // namespace
}  // namespace fabform::force_scale_test
