// Which coarser grids a scene is continued from (scene/continuation_grids.hpp), and the scenes
// that cannot be, refused in one line naming the key.
#include "fabform/scene/continuation_grids.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "fabform/error.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "test_paths.hpp"

namespace fabform::continuation_grids_test {
namespace {

TEST(ContinuationGrids, GridsHalveDownToEightDivisions) {
  Scene scene = load_scene(test::source_path("scenes/dome.toml"), {{"solver.continuation_levels", "3"}});
  EXPECT_EQ(continuation_grids(scene), (std::vector<std::array<int, 2>>{{25, 25}, {50, 50}, {100, 100}}));
  scene.fabric.divisions_warp = scene.fabric.divisions_weft = 40;
  EXPECT_EQ(continuation_grids(scene), (std::vector<std::array<int, 2>>{{10, 10}, {20, 20}}));
  scene.solver.continuation_levels = 0;
  EXPECT_TRUE(continuation_grids(scene).empty());
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

TEST(ContinuationGrids, ScenesItCannotContinueAreRefused) {
  expect_refused({{"solver.continuation_levels", "1"}, {"fabric.divisions", "[41,40]"}}, "scenes/dome.toml",
                 "solver.continuation_levels");
  expect_refused({{"solver.continuation_levels", "3"}, {"fabric.divisions", "[100,100]"}}, "scenes/dome.toml",
                 "solver.continuation_levels");  // 50, 25, then 25 does not halve
  expect_refused({{"solver.continuation_levels", "1"}, {"solver.name", "\"relax\""}}, "scenes/dome.toml", "solver.name");
  expect_refused({{"solver.continuation_levels", "1"}}, "scenes/pin.toml", "solver.continuation_levels");  // arc mesh
  expect_refused({{"solver.continuation_levels", "1"}}, "scenes/cup.toml", "solver.continuation_levels");  // load steps
}

}  // namespace
}  // namespace fabform::continuation_grids_test
