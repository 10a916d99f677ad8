// The locking angle read off a shear table by the tangents of its first and last segments.
#include <gtest/gtest.h>

#include <cmath>

#include "fabform/analysis/locking_angle.hpp"

namespace fabform::locking_angle_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(LockingAngle, DiagonalStrainOfAKnownShear) {
  // A square cell sheared by 30°: its long diagonal is √(2 + 2 sin 30°) = √3 of its side, √2 flat.
  EXPECT_NEAR(shear_angle_of_diagonal_strain_deg(std::sqrt(1.5) - 1.0), 30.0, 1e-12);
  EXPECT_NEAR(shear_angle_of_diagonal_strain_deg(0.0), 0.0, 1e-12);
  EXPECT_EQ(shear_angle_of_diagonal_strain_deg(0.5), 90.0);  // past a full shear
}

TEST(LockingAngle, TangentsOfAStiffeningTableMeet) {
  // Soft at 100 N/m, stiff at 400 N/m from (0.2, 20): 100 e = 20 + 400 (e − 0.2) at e = 0.2.
  const TensionTable table({{0.0, 0.0}, {0.1, 10.0}, {0.2, 20.0}, {0.3, 60.0}});
  const std::optional<double> locking = locking_angle_deg(table);
  ASSERT_TRUE(locking.has_value());
  EXPECT_NEAR(*locking, std::asin(1.2 * 1.2 - 1.0) * 180.0 / kPi, 1e-9);
}

TEST(LockingAngle, NoneForATableThatDoesNotStiffen) {
  EXPECT_FALSE(locking_angle_deg(TensionTable({{0.0, 0.0}, {0.1, 10.0}, {0.2, 15.0}})).has_value());
  EXPECT_FALSE(locking_angle_deg(TensionTable({{0.0, 0.0}, {0.1, 10.0}})).has_value());
}

}  // namespace
}  // namespace fabform::locking_angle_test
