// What a run warns about the strains its springs end at: beyond the measured table, and
// folded flat where nothing resists compression.
#include "fabform/model/table_range.hpp"

#include <gtest/gtest.h>

#include "support/clamped_fabric.hpp"

namespace fabform::table_range_test {
namespace {

Model flat_fabric() {
  Model model = test::clamped_fabric(4);  // linear tables measured to strain 1
  for (int k = 0; k < model.node_count(); ++k) model.start[static_cast<std::size_t>(k)] = model.fabric.rest_position(k);
  return model;
}

std::vector<Eigen::Vector3d> scaled(const Model& model, double along_x, double along_y) {
  std::vector<Eigen::Vector3d> x = model.start;
  for (auto& p : x) p = Eigen::Vector3d(along_x * p.x(), along_y * p.y(), 0.0);
  return x;
}

TEST(TableRange, WithinTheTablesNothingIsSaid) {
  const Model model = flat_fabric();
  EXPECT_TRUE(table_range_warnings(model, scaled(model, 1.5, 0.8)).empty());
}

TEST(TableRange, BeyondTheLastPointTheExtensionIsNamed) {
  const Model model = flat_fabric();
  const auto warnings = table_range_warnings(model, scaled(model, 2.5, 1.0));  // warp strain 1.5
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("20 of 20 warp springs end outside the measured range"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("reached 1.5"), std::string::npos) << warnings[0];
}

// The band of seed 003's torso, tension-only: its height folds to nothing. Said, with how far.
TEST(TableRange, FoldedFlatTensionOnlyFabricIsCalledDegenerate) {
  const Model model = flat_fabric();
  const auto warnings = table_range_warnings(model, scaled(model, 1.0, 0.03));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("20 of 20 weft springs are compressed below -50 %"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("down to -97 %"), std::string::npos) << warnings[0];
  EXPECT_TRUE(table_range_warnings(model, scaled(model, 1.0, 0.6)).empty()) << "slack is not folded";
}

// A table that carries compression resists it: compressed springs are then the table's business.
TEST(TableRange, TablesWithACompressionBranchAreNotCalledDegenerate) {
  Model model = flat_fabric();
  model.weft = TensionTable({{-0.99, -500.0}, {0.0, 0.0}, {1.0, 500.0}}, "both ways");
  EXPECT_TRUE(table_range_warnings(model, scaled(model, 1.0, 0.03)).empty());
}

}  // namespace
}  // namespace fabform::table_range_test
