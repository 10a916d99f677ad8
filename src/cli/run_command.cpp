#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <utility>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/guarded.hpp"
#include "cli/huge_pages.hpp"
#include "cli/interrupt_handlers.hpp"
#include "fabform/error.hpp"
#include "fabform/geometry/mesh_report.hpp"
#include "fabform/model/equilibrium.hpp"
#include "fabform/model/table_range.hpp"
#include "fabform/output/checkpoint.hpp"
#include "fabform/output/progress.hpp"
#include "fabform/output/result_writer.hpp"
#include "fabform/output/run_monitor.hpp"
#include "fabform/output/results_folder.hpp"
#include "fabform/output/run_inputs.hpp"
#include "fabform/run/coarse_grid_start.hpp"
#include "fabform/scene/memory_budget.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/interrupt.hpp"
#include "fabform/solver/load_steps.hpp"
#include "fabform/thread_count.hpp"

namespace fabform::cli {
namespace {

namespace fs = std::filesystem;

// The report counts a node as touching a body within 10 nm of its surface: far above the
// rounding of the solver's projections (~1e-15 m), far below any mesh's facets.
constexpr double kContactTolerance_m = 1e-8;

struct RunArguments {
  std::string scene;
  std::optional<std::string> out;
  std::optional<std::string> resume;  // a results folder to go on from
  std::vector<SceneOverride> overrides;
  bool quiet = false;
};

// Flags that are shorthands for scene keys, so they are validated like the scene itself.
const std::pair<const char*, const char*> kShorthands[] = {{"--solver", "solver.name"},
                                                           {"--tol", "solver.tolerance_N"},
                                                           {"--tol-m", "solver.tolerance_m"},
                                                           {"--max-iter", "solver.max_iterations"},
                                                           {"--threads", "solver.threads"}};

// The overrides in the order the command line gives them (a later one replaces an earlier).
std::vector<SceneOverride> overrides_in_order(const CLI::App& command) {
  std::vector<SceneOverride> overrides;
  std::map<const CLI::Option*, std::size_t> taken;
  for (const CLI::Option* option : command.parse_order()) {
    const std::string& value = option->results()[taken[option]++];
    const std::string name = option->get_name();
    if (name == "--set") overrides.push_back(parse_override(value));
    else if (name == "--unset") overrides.push_back(parse_unset(value));
    for (const auto& [flag, key] : kShorthands)
      if (name == flag) overrides.push_back({key, value});
  }
  return overrides;
}

RunArguments read_run_arguments(const CLI::App& command) {
  refuse_leftovers(command, "only one scene can be run at a time");
  RunArguments parsed;
  if (const std::string* v = given(command, "SCENE")) parsed.scene = *v;
  if (const std::string* v = given(command, "--out")) parsed.out = *v;
  if (const std::string* v = given(command, "--resume")) parsed.resume = *v;
  parsed.quiet = command.count("--quiet") > 0;
  parsed.overrides = overrides_in_order(command);
  if (parsed.resume && (!parsed.scene.empty() || parsed.out || !parsed.overrides.empty()))
    throw usage_error("--resume", "takes the scene, overrides and folder of the run it resumes; "
                                  "only --quiet may be added");
  if (parsed.scene.empty() && !parsed.resume)
    throw usage_error("SCENE", "missing: fabform run SCENE [--out DIR] | fabform run --resume DIR");
  return parsed;
}

std::string output_dir(const RunArguments& args, const Scene& scene) {
  if (args.resume) return *args.resume;
  if (args.out) return *args.out;
  if (!scene.output_dir.empty()) return scene.output_dir;
  return (fs::path("results") / scene.name).string();
}

int exit_status(Termination termination) {
  switch (termination) {
    case Termination::converged: return kExitDone;
    case Termination::numerical_failure: return kExitNumericalFailure;
    case Termination::interrupted: return kExitInterruptedBase + interrupt_signal();
    default: return kExitNotConverged;
  }
}

// What matters for contact in the bodies themselves, found once, as CGAL's checks of a large
// mesh take a while: a body contact cannot use (inverted or inconsistent faces) is refused in
// the words fabform check refuses its file with; self-intersections, and what reading the
// files skipped or tolerated, are warned about.
std::vector<std::string> body_warnings(const Scene& scene, const Model& model) {
  std::vector<std::string> warnings = model.read_warnings;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const MeshReport report = inspect_mesh(model.bodies[b].mesh());
    if (const std::string why = report.contact_refusal(); !why.empty()) throw InputError({scene.bodies[b].mesh_path, 0, ""}, why);
    for (const auto& w : report.contact_warnings()) warnings.push_back("body '" + model.bodies[b].name() + "': " + w);
  }
  return warnings;
}

// The warnings of a state: strains beyond the tables or folded flat, nodes inside a body, and
// the model's own (its bodies', a tolerance too coarse for its loads).
std::vector<std::string> collect_warnings(const Model& model, const SolverState& state,
                                          const EquilibriumReport& check, double tolerance_m,
                                          const std::vector<std::string>& of_model) {
  std::vector<std::string> warnings = table_range_warnings(model, state.x);
  if (check.max_penetration_m > tolerance_m) {
    char text[160];
    std::snprintf(text, sizeof text, "a node lies %.3g m inside a body", check.max_penetration_m);
    warnings.emplace_back(text);
  }
  if (const SpringCuts& cuts = check.spring_cuts; cuts.springs > 0) {
    const Spring& deepest = model.fabric.springs()[static_cast<std::size_t>(cuts.deepest_spring)];
    char text[320];
    std::snprintf(text, sizeof text,
                  "%d springs cut into a body between their nodes (contact is node-only), the deepest %.3g m, from %s: "
                  "refine the fabric there or round the body's edges",
                  cuts.springs, cuts.deepest_m, model.fabric.node_name(deepest.a).c_str());
    warnings.emplace_back(text);
  }
  warnings.insert(warnings.end(), of_model.begin(), of_model.end());
  return warnings;
}

// What a run starts from: the scene and overrides given, or those a resumed run recorded.
struct RunStart {
  Scene scene;
  std::vector<SceneOverride> overrides;
  std::optional<RunInputs> recorded;  // the resumed run's
};

RunStart start_of(const RunArguments& args) {
  if (!args.resume) return {load_scene(args.scene, args.overrides), args.overrides, std::nullopt};
  RunInputs recorded = read_run_inputs((fs::path(*args.resume) / "result.json").string());
  Scene scene = load_scene(recorded.scene_file, recorded.overrides);
  return {std::move(scene), recorded.overrides, std::move(recorded)};
}

// A resumed run goes on from the checkpoint's state and summary, if its inputs are unchanged.
void take_up_checkpoint(const std::string& dir, const Model& model, const RunInputs& recorded,
                        const RunInputs& now, SolverState* state, Summary* so_far) {
  const std::string result_json = (fs::path(dir) / "result.json").string();
  if (const std::string change = input_change(recorded, now); !change.empty())
    throw InputError({result_json, 0, ""}, "cannot resume: " + change);
  Checkpoint c = read_checkpoint((fs::path(dir) / "checkpoint.bin").string(), model.node_count(),
                                 static_cast<int>(model.bodies.size()));
  *state = std::move(c.state);
  *so_far = std::move(c.summary);
}

// Says what the run's last state is when it is not simply where the solver stopped.
void explain_ending(Summary* summary, const RunMonitor& monitor, const std::string& dir) {
  if (summary->termination == Termination::numerical_failure)
    summary->message += monitor.last_good_iteration() < 0
                            ? "; no state before it was good: the state written is the one found broken"
                            : "; the state written is iteration " + std::to_string(monitor.last_good_iteration()) +
                                  "'s, the last good one kept";
  if (summary->termination == Termination::interrupted)
    summary->message += "; go on with: fabform run --resume " + dir;
}

int run(const RunArguments& args) {
  const auto started = std::chrono::steady_clock::now();
  const RunStart start = start_of(args);
  restart_with_huge_pages(expected_nodes(start.scene.fabric));
  use_threads(start.scene.solver.threads);  // building the model checks every node in parallel too
  Model model = build_model(start.scene);  // its bodies travel in a run in load steps
  const Scene scene = with_tolerance_in_newtons(start.scene, model);
  const std::string dir = output_dir(args, scene);
  check_results_folder(dir);
  const RunInputs inputs = describe_inputs(scene, start.overrides);
  // Found once, as they do not change, and before any solve: a body refused for contact ends
  // the run before the coarser grids are solved.
  std::vector<std::string> of_model = body_warnings(scene, model);
  for (const auto& term : model.terms)
    if (std::string w = term->tolerance_warning(scene.solver.tolerance_N()); !w.empty()) of_model.push_back(std::move(w));
  SolverState state = SolverState::at_start(model);
  Summary so_far;
  std::vector<StepResult> finished_steps;
  if (start.recorded) {
    take_up_checkpoint(dir, model, *start.recorded, inputs, &state, &so_far);
    finished_steps = read_step_results(dir);
  }
  // A resumed run goes on from its checkpoint on the scene's own grid: the coarser ones are done.
  std::vector<ContinuationLevel> continuation;
  if (!start.recorded && scene.solver.continuation_levels > 0) {
    Continuation coarse = continue_from_coarse_grids(scene, model);
    state = std::move(coarse.start);
    continuation = std::move(coarse.levels);
    for (const ContinuationLevel& level : continuation)
      std::fprintf(stderr, "fabform: continuation grid %d x %d divisions: %s, %d iterations, residual %.3g N\n",
                   level.divisions[0], level.divisions[1], to_string(level.summary.termination).c_str(),
                   level.summary.iterations, level.summary.residual_N);
  }
  so_far = begin_summary(scene.solver.name, scene.solver.tolerance_N(), std::move(so_far), scene.solver.tolerance_m());
  std::fprintf(stderr, "fabform: scene %s, %d nodes, %zu bodies, solver %s, e = %g N%s\n",
               scene.name.c_str(), model.node_count(), model.bodies.size(),
               scene.solver.name.c_str(), scene.solver.tolerance_N(),
               start.recorded ? (", resumed after iteration " + std::to_string(so_far.iterations)).c_str() : "");
  const bool huge_pages = malloc_gets_huge_pages();
  const auto publish = [&](const SolverState& s, const Summary& summary) {
    const EquilibriumReport check = measure_equilibrium(model, s.x, kContactTolerance_m, scene.solver.tolerance_N());
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::vector<std::string> warnings = collect_warnings(model, s, check, 1e-6, of_model);
    if (std::string w = position_tolerance_warning(summary); !w.empty()) warnings.push_back(std::move(w));
    write_results(dir, RunRecord{scene, model, s, summary, check, inputs, std::move(warnings), wall,
                                 scene.solver.threads, huge_pages, &finished_steps, &continuation});
  };
  Progress progress(stderr);
  RunMonitor monitor(state, so_far, scene.checkpoint, publish, args.quiet ? nullptr : &progress);
  const InterruptHandlers handlers;
  const IterationObserver observe = [&](const IterationRecord& r) { monitor.observe(r); };
  // A finished load step is kept (replacing the one a resumed run finished again, whose cuts it
  // keeps: finished again from its own rest, it is not cut again) and checkpointed, so that the
  // run goes on from the next step.
  const StepObserver step_done = [&](int step, const SolverState& s, const Summary& of_step, StepCuts cuts) {
    const EquilibriumReport check = measure_equilibrium(model, s.x, kContactTolerance_m, scene.solver.tolerance_N());
    for (const StepResult& before : finished_steps)
      if (before.step == step && cuts.cuts == 0) cuts = before.cuts;
    StepResult result = step_result(
        RunRecord{scene, model, s, of_step, check, inputs, {}, 0.0, scene.solver.threads, huge_pages}, step, cuts);
    finished_steps.erase(std::remove_if(finished_steps.begin(), finished_steps.end(),
                                        [&](const StepResult& r) { return r.step >= step; }),
                         finished_steps.end());
    finished_steps.push_back(std::move(result));
    monitor.checkpoint();
  };
  Summary summary = model.load_steps() > 0
                        ? solve_in_steps(model, state, scene.solver, observe, step_done, std::move(so_far))
                        : solve(model, state, scene.solver, observe, std::move(so_far));
  if (!args.quiet) progress.finish();
  explain_ending(&summary, monitor, dir);
  const bool broke = summary.termination == Termination::numerical_failure && monitor.last_good_iteration() >= 0;
  try {
    publish(broke ? monitor.last_good_state() : state, summary);
  } catch (const SystemError& error) {
    std::fprintf(stderr, "fabform: error: %s; %s keeps what it held (the last checkpoint written, if any)\n",
                 error.what(), dir.c_str());
    return kExitSystemRefused;
  }
  std::fprintf(stderr, "fabform: %s: %s\nfabform: results in %s\n", to_string(summary.termination).c_str(),
               summary.message.c_str(), dir.c_str());
  return exit_status(summary.termination);
}

}  // namespace

Command add_run_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("run", "solve a scene and write its results to a folder");
  command->add_option("SCENE", "the scene file (TOML; docs in scenes/README.md)");
  command->add_option("--out", "the results folder (default: the scene's [output] dir, else results/NAME)")
      ->type_name("DIR");
  command->add_option("--resume", "go on from the checkpoint of an interrupted run's folder")->type_name("DIR");
  command->add_option("--solver", "solver.name: relax, dynamic or newton")->type_name("NAME");
  command->add_option("--tol", "solver.tolerance_N: stop once every node's unbalanced force is below it")->type_name("N");
  command->add_option("--tol-m", "solver.tolerance_m: or once the estimated distance to the rest is below it")
      ->type_name("METRES");
  command->add_option("--max-iter", "solver.max_iterations")->type_name("K");
  command->add_option("--threads", "solver.threads")->type_name("T");
  command->add_option("--set", "replace a scene value by its dotted key, e.g. fabric.divisions=[80,80]")
      ->type_name("KEY=VALUE");
  command->add_option("--unset", "remove a scene key")->type_name("KEY");
  // The shorthands and the overrides may be given again: the later one wins.
  for (CLI::Option* option : command->get_options())
    if (option->get_name() != "--help") option->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->allow_extras();
  command->add_flag("--quiet", "no progress lines");
  auto args = std::make_shared<RunArguments>();
  return {command, [command, args] { *args = read_run_arguments(*command); }, [args] { return run(*args); }};
}

}  // namespace fabform::cli
