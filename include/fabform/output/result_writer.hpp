#pragma once
// Writes a run's results into a folder: result.json (the summary other tools read),
// convergence.csv (the history), fabric.obj (the formed fabric) and fabric.vtk (ParaView, with
// per-node warp and weft strain, contact flag and residual). Each file is written to a
// temporary name and renamed, so a folder never holds a half-written file.
#include <string>
#include <vector>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/model.hpp"
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
  std::vector<std::string> warnings;
  double wall_seconds = 0.0;
  int threads = 1;
};

/// Creates the folder if needed; throws std::runtime_error naming the path if it cannot write.
void write_results(const std::string& dir, const RunRecord& run);

/// Writes `content` to path.tmp then renames it over path.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace fabform
