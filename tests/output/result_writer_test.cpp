// What result.json says about a drape that is not a tester's reading: one from a run that
// stopped short of a rest, and a negative coefficient (a shadow smaller than the support).
#include "fabform/output/result_writer.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "fabform/model/equilibrium.hpp"
#include "fabform/output/run_inputs.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/solver_state.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::result_writer_test {
namespace {

// The shipped Cusick scene, coarse, its fabric at `x`, written as a run with `summary` would be.
nlohmann::json drape_written(const std::function<void(const Scene&, std::vector<Eigen::Vector3d>*)>& move,
                             Termination termination) {
  const std::vector<SceneOverride> coarse = {{"fabric.divisions", "12"}, {"drape.clamp_radius_m", "0.05"}};
  const Scene scene = load_scene(test::source_path("scenes/cusick.toml"), coarse);
  const Model model = build_model(scene);
  SolverState state = SolverState::at_start(model);
  move(scene, &state.x);
  Summary summary = begin_summary("newton", 1e-6);
  summary.termination = termination;
  const EquilibriumReport check = measure_equilibrium(model, state.x, 1e-6, 1e-6);
  const RunInputs inputs = describe_inputs(scene, coarse);
  test::TempDir dir;
  write_results(dir.path("out"), RunRecord{scene, model, state, summary, check, inputs, {}, 0.0, 1, false, nullptr});
  std::ifstream in(dir.path("out/result.json"));
  return nlohmann::json::parse(in).at("drape");
}

void stay(const Scene&, std::vector<Eigen::Vector3d>*) {}

TEST(ResultDrape, ARestHasNoCaveat) {
  const nlohmann::json drape = drape_written(stay, Termination::converged);
  EXPECT_NEAR(drape.at("coefficient").get<double>(), 1.0, 0.05);  // flat: the shadow is the specimen
  EXPECT_TRUE(drape.at("caveats").empty()) << drape.dump();
}

TEST(ResultDrape, ARunStoppedShortIsMarked) {
  const nlohmann::json drape = drape_written(stay, Termination::not_converged);
  ASSERT_EQ(drape.at("caveats").size(), 1u) << drape.dump();
  EXPECT_EQ(drape.at("caveats")[0].get<std::string>().rfind("the run did not converge (not converged)", 0), 0u)
      << drape.dump();
}

// Every node drawn to a third of its distance from the centre: the shadow, a ninth of the
// specimen, is smaller than the 18 cm disc (0.36 of it).
TEST(ResultDrape, ANegativeCoefficientIsMarked) {
  const auto shrink = [](const Scene& scene, std::vector<Eigen::Vector3d>* x) {
    const double r = scene.fabric.radius_m();
    const Eigen::Vector2d centre = scene.origin_m.head<2>() + Eigen::Vector2d(r, r);
    for (Eigen::Vector3d& p : *x) p.head<2>() = centre + (p.head<2>() - centre) / 3.0;
  };
  const nlohmann::json drape = drape_written(shrink, Termination::converged);
  EXPECT_LT(drape.at("coefficient").get<double>(), 0.0);
  ASSERT_EQ(drape.at("caveats").size(), 1u) << drape.dump();
  EXPECT_EQ(drape.at("caveats")[0].get<std::string>().rfind("negative: the shadow is smaller than the support", 0), 0u)
      << drape.dump();
}

}  // namespace
}  // namespace fabform::result_writer_test
