#pragma once
// Writes a run's results into a folder: result.json (the summary other tools read, with the
// inputs that made it), convergence.csv (the history), fabric.obj (the formed fabric),
// fabric.vtk (ParaView, with per-node warp and weft strain, contact flag, residual, draw-in and
// contact pressure, and per-cell shear angle, thickness ratio and wrinkle risk), bodies.obj and
// bodies.vtk (the bodies where the run left them, in metres, the latter with the contact
// pressure on each vertex; not in checkpoints), the flat-formed map (print_map_files.hpp; not in
// checkpoints) and checkpoint.bin (the state to resume from) unless the run converged or broke. A run in load
// steps adds each finished step: fabric_step_K.vtp and bodies_step_K.vtp (VTK XML), the
// series fabric_steps.pvd that ParaView plays, and the step's figures under result.json's "steps". The folder is
// replaced at once (results_folder.hpp), so it never holds a half-written or mixed set.
#include <string>
#include <vector>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/model.hpp"
#include "fabform/output/run_inputs.hpp"
#include "fabform/run/coarse_grid_start.hpp"
#include "fabform/scene/scene.hpp"
#include "fabform/solver/load_steps.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

/// A finished load step's results: its entry in result.json's "steps" (JSON text) and its files.
struct StepResult {
  int step = 0;
  StepCuts cuts;  // how the step was cut (load_steps.hpp), also in its JSON
  std::string json;
  std::string fabric_vtp;
  std::string bodies_vtp;
};

struct RunRecord {
  const Scene& scene;
  const Model& model;
  const SolverState& state;
  const Summary& summary;
  const EquilibriumReport& check;  // recomputed from the final positions
  const RunInputs& inputs;
  std::vector<std::string> warnings;
  double wall_seconds = 0.0;
  int threads = 1;
  bool huge_pages = false;  // whether the process's memory came in transparent huge pages
  const std::vector<StepResult>* steps = nullptr;  // the finished load steps, in order
  // The coarser grids solved first (run/coarse_grid_start.hpp), coarsest first; null or empty: none.
  const std::vector<ContinuationLevel>* continuation = nullptr;
};

/// The results of load step `step`, `run` being its rest (its summary the step's own), `cuts`
/// how it was cut.
StepResult step_result(const RunRecord& run, int step, const StepCuts& cuts = {});

/// The finished steps a results folder holds (a resumed run's), read back from its result.json
/// and step files; throws InputError naming what is missing or damaged.
std::vector<StepResult> read_step_results(const std::string& dir);

/// Creates or replaces the folder; throws SystemError naming the path and the system's reason
/// if it cannot write, the folder then holding what it held.
void write_results(const std::string& dir, const RunRecord& run);

}  // namespace fabform
