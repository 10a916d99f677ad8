// The contact penalties' shared parts (contact_penalty.hpp): φ's slope and curvature against
// central differences on either side of the onset and across it, φ and its derivatives
// continuous at the onset, and the mean surface spring length against a rectangle's own.
#include <gtest/gtest.h>

#include <cmath>

#include "fabform/model/contact_penalty.hpp"

namespace fabform::contact_penalty_test {
namespace {

TEST(OnsetPenalty, ItsSlopeAndCurvatureAreItsDerivatives) {
  const double k = 1e5, h = 2e-4, step = 1e-10;
  for (const double depth : {1e-6, 5e-5, 1.5e-4, 2.5e-4, 1e-3, 1e-2}) {
    const OnsetPenalty at = onset_penalty(depth, k, h);
    const OnsetPenalty up = onset_penalty(depth + step, k, h), down = onset_penalty(depth - step, k, h);
    // Central differences: truncation O(step²) times the third derivative κ/h, rounding ~1e-16 φ/step.
    EXPECT_NEAR((up.value - down.value) / (2 * step), at.slope, 1e-6 * std::max(at.slope, 1e-9)) << depth;
    EXPECT_NEAR((up.slope - down.slope) / (2 * step), at.curvature, 1e-6 * k) << depth;
  }
}

TEST(OnsetPenalty, ItsStiffnessRisesToKappaOverTheOnsetAndJoinsSmoothly) {
  const double k = 3e4, h = 1e-4;
  EXPECT_EQ(onset_penalty(0.0, k, h).value, 0.0);
  EXPECT_EQ(onset_penalty(0.0, k, h).curvature, 0.0);
  const OnsetPenalty below = onset_penalty(h * (1 - 1e-12), k, h), above = onset_penalty(h, k, h);
  EXPECT_NEAR(below.value, above.value, 1e-11 * above.value);  // it moves by φ' · 1e-16 m
  EXPECT_NEAR(below.slope, above.slope, 1e-11 * above.slope);
  EXPECT_NEAR(below.curvature, k, 1e-9 * k);
  EXPECT_EQ(above.curvature, k);
  EXPECT_NEAR(onset_penalty(1e-3, k, h).slope, k * (1e-3 - h / 2), 1e-12 * k);
}

// A 4 × 1 grid of a 4 cm × 5 mm strip: eight 1 cm warp springs and five 5 mm weft springs.
TEST(MeanSurfaceSpringLength, IsTheWarpAndWeftSpringsMean) {
  EXPECT_NEAR(mean_surface_spring_length(Fabric({0.04, 0.005, 4, 1})), (8 * 0.01 + 5 * 0.005) / 13, 1e-15);
  EXPECT_TRUE(stretches_surface(SpringKind::shear));
  EXPECT_FALSE(stretches_surface(SpringKind::bend));
}

}  // namespace
}  // namespace fabform::contact_penalty_test
