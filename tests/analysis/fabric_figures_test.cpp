// Fabric figures on shapes whose areas and strains are known by hand.
#include "fabform/analysis/fabric_figures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "support/clamped_fabric.hpp"

namespace fabform::fabric_figures_test {
namespace {

// Relative to the areas here (1e-2 m²): rounding of a few hundred cell sums.
constexpr double kAreaTolerance = 1e-15;

Model flat(int divisions) {
  Model model = test::clamped_fabric(divisions);
  for (int k = 0; k < model.node_count(); ++k) model.start[static_cast<std::size_t>(k)] = model.fabric.rest_position(k);
  return model;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

TEST(FabricFigures, FlatFabricIsUnstrainedAndKeepsItsArea) {
  const Model model = flat(10);
  const FabricFigures f = fabric_figures(model, model.start, std::vector<unsigned char>(model.start.size(), 0));
  EXPECT_NEAR(f.area_flat_m2, 0.01, kAreaTolerance);
  EXPECT_NEAR(f.area_formed_m2, 0.01, kAreaTolerance);
  EXPECT_EQ(f.contact_area_m2, 0.0);
  EXPECT_NEAR(f.max_warp.strain, 0.0, 1e-14);
  EXPECT_NEAR(f.max_weft.strain, 0.0, 1e-14);
  EXPECT_NEAR(sum(f.histogram.warp_area_m2), 0.01, kAreaTolerance);
  EXPECT_NEAR(sum(f.histogram.weft_area_m2), 0.01, kAreaTolerance);
}

// Stretched 10.7 % along warp and 5.3 % along weft (away from round bin edges, where rounding
// would choose the bin): every cell has those strains, the area grows by 1.107 × 1.053, and one
// bin of each histogram holds it all.
TEST(FabricFigures, UniformStretchIsEverywhere) {
  Model model = flat(8);
  std::vector<Eigen::Vector3d> x = model.start;
  for (auto& p : x) p = Eigen::Vector3d(1.107 * p.x(), 1.053 * p.y(), 0.0);
  const FabricFigures f = fabric_figures(model, x, std::vector<unsigned char>(x.size(), 1));
  EXPECT_NEAR(f.area_formed_m2, 0.01 * 1.107 * 1.053, kAreaTolerance);
  EXPECT_NEAR(f.contact_area_m2, f.area_formed_m2, kAreaTolerance);
  EXPECT_NEAR(f.max_warp.strain, 0.107, 1e-12);
  EXPECT_NEAR(f.max_weft.strain, 0.053, 1e-12);
  EXPECT_NEAR(f.min_warp.strain, 0.107, 1e-12) << "uniform: the smallest is the largest";
  EXPECT_NEAR(f.min_weft.strain, 0.053, 1e-12);
  const StrainHistogram& h = f.histogram;
  ASSERT_EQ(h.edges.size(), h.warp_area_m2.size() + 1);
  for (std::size_t b = 0; b < h.warp_area_m2.size(); ++b) {
    const bool holds_warp = h.edges[b] <= 0.107 && 0.107 < h.edges[b + 1];
    const bool holds_weft = h.edges[b] <= 0.053 && 0.053 < h.edges[b + 1];
    EXPECT_NEAR(h.warp_area_m2[b], holds_warp ? f.area_formed_m2 : 0.0, kAreaTolerance) << b;
    EXPECT_NEAR(h.weft_area_m2[b], holds_weft ? f.area_formed_m2 : 0.0, kAreaTolerance) << b;
  }
}

// A tent: the fabric folded along its middle weft line up to height h, each half a plane
// tilted so that the warp edges stretch by √(0.05² + h²)/0.05; its one ridge carries the peak.
TEST(FabricFigures, TentHasItsAreaAndItsPeakOnTheSlope) {
  Model model = flat(10);
  std::vector<Eigen::Vector3d> x = model.start;
  const double h = 0.02;
  for (auto& p : x) p.z() = h * (1.0 - std::abs(p.x() - 0.05) / 0.05);
  const FabricFigures f = fabric_figures(model, x, std::vector<unsigned char>(x.size(), 0));
  const double slope = std::hypot(0.05, h) / 0.05;
  EXPECT_NEAR(f.area_formed_m2, 0.01 * slope, kAreaTolerance);
  EXPECT_NEAR(f.max_warp.strain, slope - 1.0, 1e-12);
  EXPECT_NEAR(f.max_weft.strain, 0.0, 1e-12);
  EXPECT_GT(f.max_warp.at_m.z(), 0.0);
}

// Gathered across the weft, more the farther along the warp: weft strain −0.4·x/W, so the
// most compressed weft springs are on the last column, at −40 %; the least compressed, on the
// first, at rest.
TEST(FabricFigures, SmallestStrainIsTheMostCompressedSpring) {
  Model model = flat(10);
  std::vector<Eigen::Vector3d> x = model.start;
  for (auto& p : x) p.y() *= 1.0 - 0.4 * p.x() / 0.1;
  const FabricFigures f = fabric_figures(model, x, std::vector<unsigned char>(x.size(), 0));
  EXPECT_NEAR(f.min_weft.strain, -0.4, 1e-12);
  EXPECT_EQ(f.min_weft.i, 10);
  EXPECT_NEAR(f.min_weft.at_m.x(), 0.1, 1e-15);
  EXPECT_NEAR(f.max_weft.strain, 0.0, 1e-12);
  EXPECT_EQ(f.max_weft.i, 0);
  EXPECT_NEAR(f.min_warp.strain, 0.0, 1e-12) << "the warp sides only tilt; those along y = 0 keep their length";
  EXPECT_EQ(f.min_warp.j, 0);
}

// Contact on one corner node only: a quarter of that corner cell's area.
TEST(FabricFigures, ContactAreaIsTheShareAroundContactNodes) {
  const Model model = flat(10);
  std::vector<unsigned char> contact(model.start.size(), 0);
  contact[static_cast<std::size_t>(model.fabric.node(0, 0))] = 1;
  EXPECT_NEAR(fabric_figures(model, model.start, contact).contact_area_m2, 0.25 * 0.01 / 100, 1e-18);
  contact[static_cast<std::size_t>(model.fabric.node(5, 5))] = 1;  // inside: four cells' quarters
  EXPECT_NEAR(fabric_figures(model, model.start, contact).contact_area_m2, 1.25 * 0.01 / 100, 1e-18);
}

TEST(FabricFigures, HistogramEdgesAreRoundAndCoverEveryCell) {
  Model model = flat(20);
  std::vector<Eigen::Vector3d> x = model.start;
  for (auto& p : x) p.x() *= 1.0 + 0.3 * p.y() / 0.1;  // warp strain 0 to 0.3 across the fabric
  const StrainHistogram h = fabric_figures(model, x, std::vector<unsigned char>(x.size(), 0)).histogram;
  EXPECT_LE(h.warp_area_m2.size(), 21u);
  for (const double edge : h.edges) {
    const double in_steps = edge / (h.edges[1] - h.edges[0]);
    EXPECT_NEAR(in_steps, std::round(in_steps), 1e-9) << edge;
  }
  EXPECT_LE(h.edges.front(), 0.0);
  EXPECT_GT(h.edges.back(), 0.29);
  EXPECT_NEAR(sum(h.warp_area_m2), sum(h.weft_area_m2), kAreaTolerance);
}

}  // namespace
}  // namespace fabform::fabric_figures_test
