// The springs' pull on a node and the deformation relax's step is taken from.
#include "fabform/model/spring_strains.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/clamped_fabric.hpp"
#include "support/rotated_fabric.hpp"

namespace fabform::spring_strains_test {
namespace {

// A fabric laid out at rest has no deformation, although its lengths, computed from turned
// and moved coordinates, differ from the rest lengths by rounding.
TEST(DeformationSum, IsZeroForAFabricLaidOutAtRest) {
  const Model model = test::rotated_fabric_at_rest(8);
  int rounded = 0;
  for (const Spring& s : model.fabric.springs()) {
    const double length = (model.start[static_cast<std::size_t>(s.b)] -
                           model.start[static_cast<std::size_t>(s.a)]).norm();
    rounded += length != s.rest_length;
  }
  ASSERT_GT(rounded, 0) << "the layout must round for this test to mean anything";
  for (int k = 0; k < model.node_count(); ++k)
    EXPECT_EQ(deformation_sum(model, model.start, k), 0.0) << "node " << k;
}

// A nanometre is far above rounding: moved along x, the centre node stretches one warp spring
// and shortens the other by it; the weft springs change by (1e-9)²/(2L), rounding, and count
// for nothing.
TEST(DeformationSum, CountsADeformationAboveRounding) {
  const Model model = test::clamped_fabric(4);
  const int centre = 12;
  std::vector<Eigen::Vector3d> x = model.start;
  x[static_cast<std::size_t>(centre)].x() += 1e-9;
  // Each term's rounding is ~16 ε · 0.1 m, 4e-16 m.
  EXPECT_NEAR(deformation_sum(model, x, centre), 2e-9, 2e-15);
}

}  // namespace
}  // namespace fabform::spring_strains_test
