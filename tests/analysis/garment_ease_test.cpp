// A garment's ease against the geometry it must give: the sewn tube's panels placed 8 cm from
// the axis of a cylinder of radius 6 cm stand 2 cm off it along their middle line, and sewn
// round it they touch it everywhere.
#include "fabform/analysis/garment_ease.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/solve.hpp"
#include "test_paths.hpp"

namespace fabform::garment_ease_test {
namespace {

// The cylinder is a 512-sided prism: its faces lie inside the circle by r (1 − cos(π/512)).
constexpr double kFacetting_m = 0.060 * (1.0 - 0.99998117528260111);

TEST(GarmentEase, PanelsStandOffTheCylinderAsPlacedAndTouchItSewn) {
  const Scene scene = load_scene(test::source_path("scenes/sewn_tube.toml"));
  const Model model = build_model(scene);
  SolverState state = SolverState::at_start(model);
  const std::optional<GarmentEase> start = garment_ease(model, state.x);
  ASSERT_TRUE(start.has_value());
  ASSERT_EQ(start->panels.size(), 2u);
  // Along each flat panel's middle (u = 0, facing the axis), the plane is 8 cm from the axis.
  for (int n = 0; n < model.node_count(); ++n)
    if (std::abs(state.x[static_cast<std::size_t>(n)].x()) < 1e-12) {
      EXPECT_NEAR(start->node_m[static_cast<std::size_t>(n)], 0.02, kFacetting_m + 1e-9) << "node " << n;
    }
  // Off the middle the plane lies further: no node nearer than 2 cm, the panels' corners at
  // hypot(7.5, 8) − 6 cm.
  for (const PanelEase& p : start->panels) {
    EXPECT_GT(p.mean_m, 0.02);
    EXPECT_NEAR(p.max_m, std::hypot(0.075, 0.08) - 0.06, kFacetting_m + 1e-9) << p.panel;
  }
  ASSERT_TRUE(solve(model, state, scene.solver).converged());
  const std::optional<GarmentEase> sewn = garment_ease(model, state.x);
  for (const PanelEase& p : sewn->panels) {
    EXPECT_LT(std::abs(p.mean_m), kFacetting_m) << p.panel;
    EXPECT_LT(p.max_m, kFacetting_m) << p.panel;
  }
}

TEST(GarmentEase, NoneWithoutPanelsOrABody) {
  const Scene tube = load_scene(test::source_path("scenes/tube.toml"));
  const Model model = build_model(tube);
  EXPECT_FALSE(garment_ease(model, SolverState::at_start(model).x).has_value());
}

}  // namespace
}  // namespace fabform::garment_ease_test
