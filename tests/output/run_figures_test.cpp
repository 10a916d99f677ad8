// The figures a run's results are written from: each the same as computed alone, and the cells
// judged by the locking angle the scene or its shear table gives.
#include "fabform/output/run_figures.hpp"

#include <gtest/gtest.h>

#include "fabform/model/equilibrium.hpp"
#include "fabform/output/run_inputs.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "test_paths.hpp"

namespace fabform::run_figures_test {
namespace {

// A coarse shipped scene at its start, as a run would record it.
struct StartedRun {
  explicit StartedRun(std::vector<SceneOverride> overrides)
      : scene(load_scene(test::source_path("scenes/dome.toml"), overrides)),
        model(build_model(scene)),
        state(SolverState::at_start(model)),
        check(measure_equilibrium(model, state.x, 1e-6, 1e-3)),
        inputs(describe_inputs(scene, overrides)) {}
  RunRecord record() const { return RunRecord{scene, model, state, summary, check, inputs, {}, 0.0, 1, false, nullptr}; }

  Scene scene;
  Model model;
  SolverState state;
  Summary summary = begin_summary("newton", 1e-3);
  EquilibriumReport check;
  RunInputs inputs;
};

const SceneOverride kCoarse{"fabric.divisions", "[10, 10]"};

TEST(RunFigures, AreEachTheFigureComputedAlone) {
  const StartedRun run({kCoarse});
  const StateFigures f = state_figures(run.record());
  const auto& x = run.state.x;
  EXPECT_EQ(f.strains.warp, node_strains(run.model, x).warp);
  EXPECT_EQ(f.draw_in.max_m, draw_in(run.model, x).max_m);
  EXPECT_EQ(f.pressure.node_Pa, contact_pressure(run.model, x, run.check.contact).node_Pa);
  EXPECT_EQ(f.fabric.area_flat_m2, fabric_figures(run.model, x, run.check.contact).area_flat_m2);
  const CellFigures cells = cell_figures(run.record());
  EXPECT_EQ(cells.deformation.shear_angle_deg, cell_deformation(run.model, x, cells.options).shear_angle_deg);
}

TEST(RunFigures, JudgeTheCellsByTheScenesLockingAngle) {
  EXPECT_STREQ(cell_figures(StartedRun({kCoarse}).record()).locking_from, "default");
  const CellFigures cells = cell_figures(StartedRun({kCoarse, {"fabric.locking_angle_deg", "30"}}).record());
  EXPECT_STREQ(cells.locking_from, "scene");
  EXPECT_EQ(cells.options.locking_angle_deg, 30.0);
}

}  // namespace
}  // namespace fabform::run_figures_test
