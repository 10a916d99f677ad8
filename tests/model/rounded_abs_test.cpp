// The rounded |x|: equal to |x| − w/2 beyond the width, x²/(2w) inside, continuous with its slope
// at ±w; slope and curvature against central differences away from the corner.
#include "fabform/model/rounded_abs.hpp"

#include <gtest/gtest.h>

namespace fabform::rounded_abs_test {
namespace {

TEST(RoundedAbs, IsAbsLessHalfTheWidthBeyondItAndQuadraticInside) {
  const double w = 0.01;
  EXPECT_DOUBLE_EQ(rounded_abs(0.3, w), 0.295);
  EXPECT_DOUBLE_EQ(rounded_abs(-0.3, w), 0.295);
  EXPECT_DOUBLE_EQ(rounded_abs(0.004, w), 0.5 * 0.004 * 0.004 / w);
  EXPECT_DOUBLE_EQ(rounded_abs(0.0, w), 0.0);
  for (const double side : {-1.0, 1.0}) {
    const double in = side * w * (1.0 - 1e-12), out = side * w * (1.0 + 1e-12);
    EXPECT_NEAR(rounded_abs(in, w), rounded_abs(out, w), 3e-12 * w);  // slope 1 over the 2e-12·w between them
    EXPECT_NEAR(rounded_abs_slope(in, w), rounded_abs_slope(out, w), 1e-10);
  }
}

TEST(RoundedAbs, SlopeAndCurvatureAreItsDerivatives) {
  const double w = 0.01, h = 1e-6;
  for (const double x : {-0.5, -0.02, -0.003, 0.0, 0.007, 0.05}) {
    EXPECT_NEAR(rounded_abs_slope(x, w), (rounded_abs(x + h, w) - rounded_abs(x - h, w)) / (2 * h), 1e-8) << x;
    EXPECT_NEAR(rounded_abs_curvature(x, w),
                (rounded_abs_slope(x + h, w) - rounded_abs_slope(x - h, w)) / (2 * h), 1e-6 / w) << x;
  }
}

}  // namespace
}  // namespace fabform::rounded_abs_test
