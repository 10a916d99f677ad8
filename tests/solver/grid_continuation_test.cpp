#include "fabform/solver/grid_continuation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fabform/error.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/newton.hpp"
#include "test_paths.hpp"

namespace fabform::grid_continuation_test {
namespace {

Fabric rectangle(int divisions_warp, int divisions_weft) {
  FabricSpec spec;
  spec.width_m = 0.12;
  spec.height_m = 0.09;
  spec.divisions_warp = divisions_warp;
  spec.divisions_weft = divisions_weft;
  return Fabric(spec);
}

// An affine displacement u(p) = A p + c, which bilinear interpolation reproduces exactly.
Eigen::Vector3d affine(const Eigen::Vector3d& flat) {
  Eigen::Matrix3d a;
  a << 0.1, -0.3, 0.0, 0.2, 0.05, 0.0, 0.7, -0.4, 0.0;
  return flat + a * flat + Eigen::Vector3d(0.01, -0.02, 0.03);
}

TEST(GridContinuation, InterpolationIsExactForAnAffineDisplacement) {
  const Fabric fine = rectangle(16, 12);
  for (const int ratio : {2, 4}) {
    const Fabric coarse = rectangle(16 / ratio, 12 / ratio);
    std::vector<Eigen::Vector3d> coarse_x;
    for (int k = 0; k < coarse.node_count(); ++k) coarse_x.push_back(affine(coarse.rest_position(k)));
    const std::vector<Eigen::Vector3d> x = interpolate_rest(coarse, coarse_x, fine);
    ASSERT_EQ(static_cast<int>(x.size()), fine.node_count());
    for (int k = 0; k < fine.node_count(); ++k)
      EXPECT_LT((x[static_cast<std::size_t>(k)] - affine(fine.rest_position(k))).norm(), 1e-15)
          << fine.node_name(k) << ", ratio " << ratio;
  }
}

TEST(GridContinuation, GridsHalveDownToEightDivisions) {
  Scene scene = load_scene(test::source_path("scenes/dome.toml"), {{"solver.continuation_levels", "3"}});
  EXPECT_EQ(continuation_grids(scene), (std::vector<std::array<int, 2>>{{25, 25}, {50, 50}, {100, 100}}));
  scene.fabric.divisions_warp = scene.fabric.divisions_weft = 40;
  EXPECT_EQ(continuation_grids(scene), (std::vector<std::array<int, 2>>{{10, 10}, {20, 20}}));
  scene.solver.continuation_levels = 0;
  EXPECT_TRUE(continuation_grids(scene).empty());
}

double largest_distance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, (a[i] - b[i]).norm());
  return largest;
}

// The dome at 41 × 41 nodes from the 21 × 21 and 11 × 11 rests, in fewer iterations on the
// scene's own grid. The faceted hemisphere has several rests (README, "Faceted bodies have
// several rests"), and the continued solve ends on a neighbour of the plain solve's: each run is
// within 1e-7 m (a 2500th of the 0.25 mm spacing) of its own path's rest at 1e-12 N, and the two
// rests lie 2.4e-5 m apart, under a tenth of the spacing (the bound here: 0.15 of it). With the
// exact matrix, as measured (with the scene's slack floor the run at e ends 1.2e-7 m from its 1e-12 N rest).
TEST(GridContinuation, ContinuedDomeReachesANeighbouringRestInFewerIterations) {
  const Scene scene = load_scene(test::source_path("scenes/dome.toml"), {{"fabric.divisions", "[40,40]"},
                                                                          {"solver.continuation_levels", "2"},
                                                                          {"solver.slack_stiffness", "0"}});
  const Model model = build_model(scene);
  const Continuation continued = continue_from_coarse_grids(scene, model);
  ASSERT_EQ(continued.levels.size(), 2u);
  for (const ContinuationLevel& level : continued.levels) {
    EXPECT_TRUE(level.summary.converged()) << level.summary.message;
    EXPECT_TRUE(std::isnan(level.summary.position_error_m));  // a start, not an answer: no estimate
  }
  const auto solve_from = [&](SolverState state, double tolerance_N, Summary* summary) {
    NewtonOptions options = scene.solver.newton;
    options.tolerance_N = tolerance_N;
    *summary = newton(model, state, options);
    EXPECT_TRUE(summary->converged()) << summary->message;
    return state.x;
  };
  Summary plain, from_coarse, tight;
  const auto plain_rest = solve_from(SolverState::at_start(model), 1e-12, &tight);
  const auto continued_rest = solve_from(continued.start, 1e-12, &tight);
  const auto x_plain = solve_from(SolverState::at_start(model), scene.solver.tolerance_N(), &plain);
  const auto x_continued = solve_from(continued.start, scene.solver.tolerance_N(), &from_coarse);
  EXPECT_LT(largest_distance(x_plain, plain_rest), 1e-7);
  EXPECT_LT(largest_distance(x_continued, continued_rest), 1e-7);
  const double spacing = model.fabric.spacing_warp();
  EXPECT_LT(largest_distance(x_continued, x_plain), 0.15 * spacing);
  std::printf("continued rest %.3g m from the plain rest; iterations %d against %d\n",
              largest_distance(continued_rest, plain_rest), from_coarse.iterations, plain.iterations);
  EXPECT_LT(from_coarse.iterations, plain.iterations);
}

TEST(GridContinuation, ANodeOnAFacetWithinRoundingStartsInContact) {
  // Interpolated between two coarse nodes on one facet, a node lies on it up to rounding, above
  // as often as below; either way it starts in contact, on the surface, while a node clearly
  // above (four times the margin) stays free where it is.
  const Scene scene = load_scene(test::source_path("scenes/dome.toml"), {{"fabric.divisions", "[20,20]"}});
  const Model model = build_model(scene);
  const RigidBody& dome = model.bodies.front();
  const double margin = dome.on_surface_distance();
  const int centre = 10 * 21 + 10;
  ASSERT_EQ(model.locks[centre], 0);
  const Eigen::Vector3d above_top = model.fabric.rest_position(centre) + Eigen::Vector3d(0.001, 0.002, 0.05);
  const SurfacePoint top = dome.closest(above_top);
  for (const double height : {-0.5, 0.0, 0.5, 4.0}) {
    SCOPED_TRACE(testing::Message() << height << " margins above the surface");
    std::vector<Eigen::Vector3d> interpolated = model.start;
    interpolated[centre] = top.point + height * margin * top.normal;
    const SolverState start = continued_start(model, interpolated);
    const bool on_surface = height <= 1.0;
    EXPECT_EQ(start.contact[centre].active(), on_surface);
    if (on_surface) EXPECT_LE((start.x[centre] - top.point).norm(), 1e-12 * dome.box().diagonal());
    else EXPECT_EQ(start.x[centre], interpolated[centre]);
  }
}

// The key's refusals are one line naming the key that must change.
void expect_refused(const std::vector<SceneOverride>& overrides, const std::string& scene, const std::string& key) {
  try {
    load_scene(test::source_path(scene), overrides);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find(key + ":"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(GridContinuation, ScenesItCannotContinueAreRefused) {
  expect_refused({{"solver.continuation_levels", "1"}, {"fabric.divisions", "[41,40]"}}, "scenes/dome.toml",
                 "solver.continuation_levels");
  expect_refused({{"solver.continuation_levels", "3"}, {"fabric.divisions", "[100,100]"}}, "scenes/dome.toml",
                 "solver.continuation_levels");  // 50, 25, then 25 does not halve
  expect_refused({{"solver.continuation_levels", "1"}, {"solver.name", "\"relax\""}}, "scenes/dome.toml", "solver.name");
  expect_refused({{"solver.continuation_levels", "1"}}, "scenes/pin.toml", "solver.continuation_levels");  // arc mesh
  expect_refused({{"solver.continuation_levels", "1"}}, "scenes/cup.toml", "solver.continuation_levels");  // load steps
}

}  // namespace
}  // namespace fabform::grid_continuation_test
