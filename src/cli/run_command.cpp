#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/commands.hpp"
#include "fabform/error.hpp"
#include "fabform/geometry/mesh_report.hpp"
#include "fabform/model/equilibrium.hpp"
#include "fabform/model/table_range.hpp"
#include "fabform/output/progress.hpp"
#include "fabform/output/result_writer.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"

namespace fabform::cli {
namespace {

namespace fs = std::filesystem;

// The report counts a node as touching a body within 10 nm of its surface: far above the
// rounding of the solver's projections (~1e-15 m), far below any mesh's facets.
constexpr double kContactTolerance_m = 1e-8;

struct RunArguments {
  std::string scene;
  std::optional<std::string> out;
  std::vector<SceneOverride> overrides;
  bool quiet = false;
};

// Flags that are shorthands for scene keys, so they are validated like the scene itself.
const std::pair<const char*, const char*> kShorthands[] = {{"--solver", "solver.name"},
                                                           {"--tol", "solver.tolerance_N"},
                                                           {"--max-iter", "solver.max_iterations"},
                                                           {"--threads", "solver.threads"}};

RunArguments parse_arguments(const std::vector<std::string>& args) {
  RunArguments parsed;
  const auto usage_error = [](const std::string& flag, const std::string& why) {
    return InputError({"command line", 0, flag}, why);
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw usage_error(a, "needs a value");
      return args[++i];
    };
    bool shorthand = false;
    for (const auto& [flag, key] : kShorthands)
      if (a == flag) parsed.overrides.push_back({key, value()}), shorthand = true;
    if (shorthand) continue;
    if (a == "--out") parsed.out = value();
    else if (a == "--set") parsed.overrides.push_back(parse_override(value()));
    else if (a == "--quiet") parsed.quiet = true;
    else if (!a.empty() && a[0] == '-') throw usage_error(a, "unknown option");
    else if (parsed.scene.empty()) parsed.scene = a;
    else throw usage_error(a, "only one scene can be run at a time");
  }
  if (parsed.scene.empty()) throw usage_error("SCENE", "missing: fabform run SCENE [--out DIR]");
  return parsed;
}

std::string output_dir(const RunArguments& args, const Scene& scene) {
  if (args.out) return *args.out;
  if (!scene.output_dir.empty()) return scene.output_dir;
  return (fs::path("results") / scene.name).string();
}

// Fails before a long solve, not after it, when the results could not be written.
void check_writable(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  const std::string probe = (fs::path(dir) / ".fabform-write-probe").string();
  std::FILE* f = ec ? nullptr : std::fopen(probe.c_str(), "w");
  if (!f) throw InputError({dir, 0, ""}, "the output folder cannot be written");
  std::fclose(f);
  std::remove(probe.c_str());
}

int exit_status(Termination termination) {
  switch (termination) {
    case Termination::converged: return kExitDone;
    case Termination::numerical_failure: return kExitNumericalFailure;
    default: return kExitNotConverged;
  }
}

std::vector<std::string> collect_warnings(const Model& model, const SolverState& state,
                                          const EquilibriumReport& check, double tolerance_m) {
  std::vector<std::string> warnings = table_range_warnings(model, state.x);
  if (check.max_penetration_m > tolerance_m) {
    char text[160];
    std::snprintf(text, sizeof text, "a node lies %.3g m inside a body", check.max_penetration_m);
    warnings.emplace_back(text);
  }
  for (const RigidBody& body : model.bodies)  // an open mold is fine; inverted normals are not
    for (const auto& w : inspect_mesh(body.mesh()).contact_warnings()) warnings.push_back("body '" + body.name() + "': " + w);
  return warnings;
}

int run(const RunArguments& args) {
  const auto started = std::chrono::steady_clock::now();
  const Scene scene = load_scene(args.scene, args.overrides);
  const Model model = build_model(scene);
  const std::string dir = output_dir(args, scene);
  check_writable(dir);
  std::fprintf(stderr, "fabform: scene %s, %d nodes, %zu bodies, solver %s, e = %g N\n",
               scene.name.c_str(), model.node_count(), model.bodies.size(),
               scene.solver.name.c_str(), scene.solver.tolerance_N());
  Progress progress(stderr);
  SolverState state = SolverState::at_start(model);
  const Summary summary = solve(model, state, scene.solver, [&](const IterationRecord& r) {
    if (!args.quiet) progress.update(r);
  });
  if (!args.quiet) progress.finish();
  const EquilibriumReport check = measure_equilibrium(model, state.x, kContactTolerance_m);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  RunRecord record{scene, model, state, summary, check,
                   collect_warnings(model, state, check, 1e-6), wall, scene.solver.threads};
  write_results(dir, record);
  for (const auto& w : record.warnings) std::fprintf(stderr, "fabform: warning: %s\n", w.c_str());
  std::fprintf(stderr, "fabform: %s: %s\nfabform: results in %s\n", to_string(summary.termination).c_str(),
               summary.message.c_str(), dir.c_str());
  return exit_status(summary.termination);
}

}  // namespace

int run_command(const std::vector<std::string>& args) {
  try {
    return run(parse_arguments(args));
  } catch (const InputError& error) {
    std::fprintf(stderr, "fabform: error: %s\n", error.what());
    return kExitBadInput;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "fabform: error: %s\n", error.what());
    return kExitBadInput;
  }
}

}  // namespace fabform::cli
