#pragma once
// Writes a run's results into a folder: result.json (the summary other tools read, with the
// inputs that made it), convergence.csv (the history), fabric.obj (the formed fabric),
// fabric.vtk (ParaView, with per-node warp and weft strain, contact flag and residual),
// bodies.obj (the bodies as placed, in metres; not in checkpoints) and checkpoint.bin (the
// state to resume from) unless the run converged or broke. The folder is
// replaced at once (results_folder.hpp), so it never holds a half-written or mixed set.
#include <string>
#include <vector>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/model.hpp"
#include "fabform/output/run_inputs.hpp"
#include "fabform/scene/scene.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

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
};

/// Creates or replaces the folder; throws std::runtime_error naming the path if it cannot write.
void write_results(const std::string& dir, const RunRecord& run);

/// Writes `content` to path.tmp then renames it over path.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace fabform
