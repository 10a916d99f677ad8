// The scene reader's refusals of a solver (scene_toml.cpp, at solver.name) and the solvers' own
// check of a model (solver_refusal) ask one table: over every shipped scene and every solver, the
// reader refuses the solver exactly where the scene's model needs what that solver does not give.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "fabform/error.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/solver_registry.hpp"
#include "test_paths.hpp"

namespace fabform::solver_refusals_test {
namespace {

TEST(SolverRefusals, TheReaderRefusesASolverExactlyWhereTheModelNeedsMore) {
  int scenes = 0, refused = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes"))) {
    if (entry.path().extension() != ".toml") continue;
    const std::string path = entry.path().string();
    const Model model = build_model(load_scene(path));
    ++scenes;
    for (const SolverEntry& solver : solvers()) {
      SCOPED_TRACE(path + " with " + solver.name);
      const std::string lacking = solver_refusal(model, solver.name);
      try {
        load_scene(path, {{"solver.name", "\"" + solver.name + "\""}});
        EXPECT_EQ(lacking, "");
      } catch (const InputError& error) {
        const std::string what = error.what();
        if (what.find("solver.name:") == std::string::npos) continue;  // refused for another key's sake
        EXPECT_NE(lacking, "") << what;
        ++refused;
      }
    }
  }
  EXPECT_GE(scenes, 14);
  EXPECT_GE(refused, 10);  // the table does refuse
}

}  // namespace
}  // namespace fabform::solver_refusals_test
