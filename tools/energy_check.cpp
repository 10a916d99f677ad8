// Whether a run's state has the energy its forces say (analysis/energy_consistency.hpp): from the
// checkpoint.bin of a run that stopped unconverged (a converged run keeps none), with the scene
// and --set overrides its result.json recorded, the bodies where the checkpoint's load step has
// them. Lists up to ten nodes that disagree, the largest gap first, with the term that differs
// most. Exit status 0: every node agrees; 1: some do not; 2: bad input.
//   build/fabform_energy_check RESULTS_DIR
#include <cstdio>
#include <exception>
#include <string>

#include "fabform/analysis/energy_consistency.hpp"
#include "fabform/output/checkpoint.hpp"
#include "fabform/output/run_inputs.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/load_steps.hpp"

namespace {

int check(const std::string& dir) {
  const fabform::RunInputs inputs = fabform::read_run_inputs(dir + "/result.json");
  fabform::Model model = fabform::build_model(fabform::load_scene(inputs.scene_file, inputs.overrides));
  const fabform::Checkpoint checkpoint = fabform::read_checkpoint(dir + "/checkpoint.bin", model.node_count(),
                                                                  static_cast<int>(model.bodies.size()));
  if (!checkpoint.summary.history.empty() && checkpoint.summary.history.back().step > 0)
    fabform::stand_bodies_at_step(model, checkpoint.summary.history.back().step);
  const fabform::EnergyConsistency result = fabform::check_energy_consistency(model, checkpoint.state);
  std::printf("energy_check: %d free nodes with a force above %g N moved 1e-09 m along it and against it; "
              "%zu disagree\n",
              result.checked, fabform::kSmallestForceN, result.disagreeing.size());
  for (std::size_t k = 0; k < result.disagreeing.size() && k < 10; ++k) {
    const fabform::EnergyDisagreement& d = result.disagreeing[k];
    std::printf("  node %d: |R| %.4g N, change of energy %.4g J against %.4g J predicted (%s)\n", d.node, d.force_N,
                d.measured_J, d.predicted_J, d.term.c_str());
  }
  return result.disagreeing.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fabform_energy_check RESULTS_DIR\n");
    return 2;
  }
  try {
    return check(argv[1]);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "fabform_energy_check: error: %s\n", error.what());
    return 2;
  }
}
