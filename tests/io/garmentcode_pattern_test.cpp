// GarmentCode's shipped patterns read as GarmentCode draws them: panel and stitch counts, the
// necklines' arcs centred on the garment's centre line (x = 0, where GarmentCode's designs put
// them), and every panel meshed on the lattice at the spacings a garment is simulated at.
#include "fabform/io/garmentcode_pattern.hpp"

#include <gtest/gtest.h>

#include <string>

#include "fabform/fabric/fabric.hpp"
#include "test_paths.hpp"

namespace fabform::garmentcode_pattern_test {
namespace {

SewingPattern shipped(const std::string& name) {
  return read_garmentcode_pattern(test::source_path("garments/garmentcode_" + name + "_specification.json"), 90.0);
}

TEST(GarmentCodePattern, ReadsTheShippedPatternsPanelsAndStitches) {
  struct Count {
    const char* name;
    std::size_t panels, stitches;
  };
  for (const Count& c : {Count{"shirt_mean", 8, 18}, Count{"hoody_mean", 6, 12}, Count{"dress_pencil", 6, 23}}) {
    const SewingPattern p = shipped(c.name);
    EXPECT_EQ(p.panels.size(), c.panels) << c.name;
    EXPECT_EQ(p.stitches.size(), c.stitches) << c.name;
    for (const PanelSpec& panel : p.panels) EXPECT_EQ(panel.outline.invalid_reason(), "") << c.name << " " << panel.name;
  }
}

// The circumcentre of three points of an arc.
Eigen::Vector2d centre_of(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double d = 2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
  const auto sq = [](const Eigen::Vector2d& p) { return p.squaredNorm(); };
  return {(sq(a) * (b.y() - c.y()) + sq(b) * (c.y() - a.y()) + sq(c) * (a.y() - b.y())) / d,
          (sq(a) * (c.x() - b.x()) + sq(b) * (a.x() - c.x()) + sq(c) * (b.x() - a.x())) / d};
}

// The hoody's necklines are circle arcs ([radius, large_arc, right]); drawn with SVG's flags the
// way GarmentCode's mesher reads them, each arc's circle is centred on the centre line x = 0.
TEST(GarmentCodePattern, TheHoodysNecklineArcsAreCentredOnTheCentreLine) {
  const SewingPattern p = shipped("hoody_mean");
  int arcs = 0;
  for (const PanelSpec& panel : p.panels)
    for (std::size_t k = 0; k < panel.outline.edges.size(); ++k) {
      const OutlineEdge& e = panel.outline.edges[k];
      if (e.kind != OutlineEdge::Kind::arc) continue;
      ++arcs;
      const int edge = static_cast<int>(k);
      const Eigen::Vector2d centre = centre_of(panel.outline.point(edge, 0.0), panel.outline.point(edge, 0.5), panel.outline.point(edge, 1.0));
      EXPECT_NEAR(centre.x(), 0.0, 1e-6) << panel.name << " edge " << k;
      EXPECT_NEAR((panel.outline.point(edge, 0.3) - centre).norm(), e.radius_m, 1e-9) << panel.name;
    }
  EXPECT_EQ(arcs, 4);
}

struct Meshing {
  const char* pattern;
  double spacing_m;
};

class GarmentCodeMeshing : public ::testing::TestWithParam<Meshing> {};

TEST_P(GarmentCodeMeshing, EveryPanelMeshesOnTheLattice) {
  FabricSpec spec;
  spec.shape = FabricSpec::Shape::panels;
  spec.panels = shipped(GetParam().pattern).panels;
  spec.panel_spacing_m = {GetParam().spacing_m, GetParam().spacing_m};
  const Fabric f(spec);
  EXPECT_EQ(f.panels().size(), spec.panels.size());
}

INSTANTIATE_TEST_SUITE_P(Shipped, GarmentCodeMeshing,
                         ::testing::Values(Meshing{"shirt_mean", 0.0025}, Meshing{"shirt_mean", 0.005},
                                           Meshing{"shirt_mean", 0.0075}, Meshing{"shirt_mean", 0.01},
                                           Meshing{"shirt_mean", 0.015}, Meshing{"shirt_mean", 0.02},
                                           Meshing{"hoody_mean", 0.0025}, Meshing{"hoody_mean", 0.005},
                                           Meshing{"hoody_mean", 0.0075}, Meshing{"hoody_mean", 0.01},
                                           Meshing{"hoody_mean", 0.015}, Meshing{"hoody_mean", 0.02}),
                         [](const auto& meshing) {
                           return std::string(meshing.param.pattern) + "_" + std::to_string(static_cast<int>(meshing.param.spacing_m * 1e4)) + "_tenths_mm";
                         });

// The pencil dress's darts are sharp notches in its back skirt: no lattice follows them yet.
TEST(GarmentCodeMeshing, ThePencilDressesDartsAreRefusedByName) {
  FabricSpec spec;
  spec.shape = FabricSpec::Shape::panels;
  spec.panels = shipped("dress_pencil").panels;
  spec.panel_spacing_m = {0.01, 0.01};
  try {
    Fabric f(spec);
    FAIL() << "the darts meshed: docs/garments.md says they do not";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("panel 'skirt_back': ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace fabform::garmentcode_pattern_test
