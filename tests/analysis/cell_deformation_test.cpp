// Shear angle, thickness ratio and wrinkle risk on deformations known by hand: a simple shear
// x' = x + y tan γ turns the angle between warp and weft from 90° to 90° − γ and keeps every
// area (thickness ratio 1); a stretch by λ1 along warp and λ2 along weft keeps the right angle
// and thins every cell to 1 / (λ1 λ2). Tolerances: 1e-9 degrees and 1e-12 relative, rounding
// only (the maps are affine, so every cell sees them exactly).
#include <gtest/gtest.h>

#include <cmath>

#include "fabform/analysis/cell_deformation.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::cell_deformation_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The 10 × 10 cm, 8 × 8 cell test fabric with every node moved by `map` from its flat place.
template <typename Map>
std::vector<Eigen::Vector3d> mapped(const Model& model, Map map) {
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < model.node_count(); ++k) x.push_back(map(model.fabric.rest_position(k)));
  return x;
}

TEST(CellDeformation, SimpleShearGivesItsAngleAndKeepsTheThickness) {
  const Model model = test::clamped_fabric(8);
  for (const double gamma_deg : {5.0, 30.0, -20.0}) {
    const double t = std::tan(gamma_deg * kPi / 180.0);
    const auto x = mapped(model, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x() + t * p.y(), p.y(), 0.0); });
    const CellDeformation d = cell_deformation(model, x, {});
    ASSERT_EQ(d.shear_angle_deg.size(), model.fabric.faces().size());
    for (std::size_t f = 0; f < d.shear_angle_deg.size(); ++f) {
      EXPECT_NEAR(d.shear_angle_deg[f], gamma_deg, 1e-9) << f;
      EXPECT_NEAR(d.thickness_ratio[f], 1.0, 1e-12) << f;
    }
    EXPECT_NEAR(d.shear_angle_max_deg, std::abs(gamma_deg), 1e-9);
    EXPECT_EQ(d.wrinkle_cells, 0) << "below the 45° default locking angle";
  }
}

TEST(CellDeformation, StretchThinsToOneOverTheProductOfTheStretches) {
  const Model model = test::clamped_fabric(8);
  const double l1 = 1.2, l2 = 1.05;
  const auto x = mapped(model, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(l1 * p.x(), l2 * p.y(), 0.3 * p.x()); });
  const CellDeformation d = cell_deformation(model, x, {});
  // The tilt (z = 0.3 x) stretches warp by √(l1² + 0.09) and keeps the right angle.
  const double warp = std::sqrt(l1 * l1 + 0.09);
  for (std::size_t f = 0; f < d.thickness_ratio.size(); ++f) {
    EXPECT_NEAR(d.thickness_ratio[f], 1.0 / (warp * l2), 1e-12) << f;
    EXPECT_NEAR(d.shear_angle_deg[f], 0.0, 1e-9) << f;
  }
  EXPECT_NEAR(d.thickness_ratio_min, 1.0 / (warp * l2), 1e-12);
  EXPECT_EQ(d.wrinkle_cells, 0);
}

TEST(CellDeformation, LockedOrDoublyCompressedCellsRiskWrinkles) {
  const Model model = test::clamped_fabric(8);
  const auto sheared = mapped(model, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x() + p.y(), p.y(), 0.0); });
  CellDeformationOptions options;
  options.locking_angle_deg = 44.0;  // the shear is 45°
  EXPECT_EQ(cell_deformation(model, sheared, options).wrinkle_cells, 64);
  options.locking_angle_deg = 46.0;
  EXPECT_EQ(cell_deformation(model, sheared, options).wrinkle_cells, 0);

  const auto shrunk = mapped(model, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(0.9 * p.x(), 0.95 * p.y(), 0.0); });
  const CellDeformation both = cell_deformation(model, shrunk, {});
  EXPECT_EQ(both.wrinkle_cells, 64);
  EXPECT_EQ(both.wrinkle_risk.front(), 1);
  const auto one_way = mapped(model, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(0.9 * p.x(), 1.05 * p.y(), 0.0); });
  EXPECT_EQ(cell_deformation(model, one_way, {}).wrinkle_cells, 0) << "compressed one way only: it can still shear";
}

TEST(CellDeformation, RefusesLockingAnglesOutsideAQuarterTurn) {
  const Model model = test::clamped_fabric(2);
  for (const double bad : {0.0, 90.0, -5.0, std::nan("")}) {
    CellDeformationOptions options;
    options.locking_angle_deg = bad;
    EXPECT_FALSE(options.invalid_reason().empty()) << bad;
    EXPECT_THROW(cell_deformation(model, model.start, options), std::invalid_argument) << bad;
  }
}

}  // namespace
}  // namespace fabform::cell_deformation_test
