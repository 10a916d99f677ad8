// The drape figures on shapes whose answer is known: a flat circle (DC 1, no folds, whatever its
// mesh), one shrunk towards its centre (DC the square of the factor) and one pushed into n lobes
// (n folds).
#include "fabform/analysis/drape_figures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fabform::drape_figures_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

FabricSpec circle(FabricSpec::Mesh mesh, int divisions) {
  FabricSpec spec{0.3, 0.3, divisions, divisions};
  spec.shape = FabricSpec::Shape::circle;
  spec.mesh = mesh;
  spec.rings = divisions / 2;
  spec.spokes = 2 * divisions;
  return spec;
}

const Eigen::Vector2d kCentre(0.15, 0.15);

// Each node moved radially in the plane: its distance from the centre times radius(angle).
template <typename Radius>
std::vector<Eigen::Vector3d> reshaped(const Fabric& fabric, Radius radius) {
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < fabric.node_count(); ++k) {
    const Eigen::Vector3d p = fabric.rest_position(k);
    const Eigen::Vector2d d = p.head<2>() - kCentre;
    const double factor = radius(std::atan2(d.y(), d.x()));
    x.emplace_back(kCentre.x() + factor * d.x(), kCentre.y() + factor * d.y(), -0.01);
  }
  return x;
}

class EveryMesh : public ::testing::TestWithParam<std::pair<FabricSpec::Mesh, int>> {};

TEST_P(EveryMesh, FlatCircleHasDCOneAndNoFolds) {
  const Fabric fabric(circle(GetParam().first, GetParam().second));
  const DrapeFigures f = drape_figures(fabric, reshaped(fabric, [](double) { return 1.0; }), kCentre, 0.0);
  EXPECT_NEAR(f.coefficient, 1.0, 1e-12);
  EXPECT_EQ(f.folds, 0);
  EXPECT_EQ(f.shadow_pieces, 1);
}

// A disc of a quarter of the specimen's area under it: DC counts only what lies beyond it.
TEST_P(EveryMesh, ShrunkCircleHasDCOfItsAreaBeyondTheDisc) {
  const Fabric fabric(circle(GetParam().first, GetParam().second));
  const double disc = 0.25 * fabric.flat_area();
  const DrapeFigures f = drape_figures(fabric, reshaped(fabric, [](double) { return 0.8; }), kCentre, disc);
  EXPECT_NEAR(f.shadow_area_m2, 0.64 * fabric.flat_area(), 1e-12);
  EXPECT_NEAR(f.coefficient, (0.64 - 0.25) / 0.75, 1e-12);
}

TEST_P(EveryMesh, LobedOutlineHasAFoldPerLobe) {
  const Fabric fabric(circle(GetParam().first, GetParam().second));
  for (const int lobes : {3, 5, 8}) {
    const auto radius = [&](double angle) { return 0.8 + 0.1 * std::cos(lobes * angle + 0.3); };
    EXPECT_EQ(drape_figures(fabric, reshaped(fabric, radius), kCentre, 0.0).folds, lobes) << lobes << " lobes";
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, EveryMesh,
                         ::testing::Values(std::pair{FabricSpec::Mesh::quadrangular, 24},
                                           std::pair{FabricSpec::Mesh::quadrangular, 40},
                                           std::pair{FabricSpec::Mesh::quadrangular, 80},
                                           std::pair{FabricSpec::Mesh::triangular, 41},
                                           std::pair{FabricSpec::Mesh::arc, 32}),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param.first)) + std::to_string(param_info.param.second);
                         });

TEST(FabricTriangles, CoverTheFacesOnce) {
  const Fabric fabric(circle(FabricSpec::Mesh::arc, 10));
  double area = 0.0;
  for (const auto& t : face_triangles(fabric.faces())) {
    const Eigen::Vector3d a = fabric.rest_position(t[0]), b = fabric.rest_position(t[1]), c = fabric.rest_position(t[2]);
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  EXPECT_NEAR(area, fabric.flat_area(), 1e-15);
  EXPECT_NEAR(fabric.flat_area(), 0.5 * 20 * 0.15 * 0.15 * std::sin(2 * kPi / 20), 1e-15);
}

}  // namespace
}  // namespace fabform::drape_figures_test
