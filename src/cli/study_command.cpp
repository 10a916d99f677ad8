#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/guarded.hpp"
#include "cli/interrupt_handlers.hpp"
#include "fabform/error.hpp"
#include "fabform/solver/interrupt.hpp"
#include "fabform/study/child_process.hpp"
#include "fabform/study/local_pool.hpp"
#include "fabform/study/slurm_backend.hpp"
#include "fabform/study/specimen_summary.hpp"
#include "fabform/study/study_case.hpp"
#include "fabform/study/study_file.hpp"
#include "fabform/study/study_record.hpp"
#include "fabform/study/study_table.hpp"

namespace fabform::cli {
namespace {

namespace fs = std::filesystem;

struct StudyArguments {
  std::string study;                  // a study file, or
  std::optional<std::string> resume;  // a study folder to go on with
  std::optional<std::string> out;
  std::string on = "local";
  int jobs = 0;              // 0: local, one case per core; Slurm, no throttle
  int threads_per_case = 0;  // 0: cores / jobs locally, 1 on Slurm
  std::string partition;
  int time_limit_min = 0;
  int mem_mb = 0;
  bool quiet = false;
};

int count_value(const std::string& flag, const std::string& text, int high) {
  std::size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || value < 1 || value > high)
    throw usage_error(flag, "must be a whole number from 1 to " + std::to_string(high));
  return value;
}

StudyArguments read_study_arguments(const CLI::App& command) {
  refuse_leftovers(command, "only one study can be run at a time");
  StudyArguments parsed;
  if (const std::string* v = given(command, "STUDY")) parsed.study = *v;
  if (const std::string* v = given(command, "--out")) parsed.out = *v;
  if (const std::string* v = given(command, "--resume")) parsed.resume = *v;
  if (const std::string* v = given(command, "--on")) parsed.on = *v;
  if (const std::string* v = given(command, "--jobs")) parsed.jobs = count_value("--jobs", *v, 10000);
  if (const std::string* v = given(command, "--threads-per-case")) parsed.threads_per_case = count_value("--threads-per-case", *v, 1024);
  if (const std::string* v = given(command, "--partition")) parsed.partition = *v;
  if (const std::string* v = given(command, "--time-limit")) parsed.time_limit_min = count_value("--time-limit", *v, 10000000);
  if (const std::string* v = given(command, "--mem-mb")) parsed.mem_mb = count_value("--mem-mb", *v, 100000000);
  parsed.quiet = command.count("--quiet") > 0;
  if (parsed.on != "local" && parsed.on != "slurm") throw usage_error("--on", "must be local or slurm");
  if (parsed.on == "local" && (!parsed.partition.empty() || parsed.time_limit_min || parsed.mem_mb))
    throw usage_error(!parsed.partition.empty() ? "--partition" : parsed.time_limit_min ? "--time-limit" : "--mem-mb",
                      "is a Slurm option: add --on slurm");
  if (parsed.partition.find_first_of(" \t\n'\"") != std::string::npos) throw usage_error("--partition", "is not a partition name");
  if (parsed.resume && (!parsed.study.empty() || parsed.out))
    throw usage_error("--resume", "takes the study and folder it goes on with: fabform study --resume DIR");
  if (parsed.study.empty() && !parsed.resume)
    throw usage_error("STUDY", "missing: fabform study STUDY.toml --out DIR | fabform study --resume DIR");
  return parsed;
}

// A new study's folder is new or empty: it is never mixed with another study's or run's files.
void check_new_study_folder(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (fs::exists(study_record_path(dir), ec))
    throw usage_error("--out", dir + " holds a study already: go on with it with fabform study --resume " + dir);
  if (!fs::is_directory(dir, ec) || !fs::is_empty(dir, ec))
    throw usage_error("--out", dir + " is not an empty folder");
}

// study.html, by tools/study_report.py; a study without it is still whole (its table is).
void write_report(const std::string& dir) {
  const CommandOutput report = run_process({"/usr/bin/python3", std::string(FABFORM_TOOLS_DIR) + "/study_report.py", dir});
  if (report.status != 0)
    std::fprintf(stderr, "fabform: warning: study.html not written: %s", report.err.empty() ? "study_report.py failed\n" : report.err.c_str());
}

int study(const StudyArguments& args) {
  const bool resuming = args.resume.has_value();
  StudySpec spec;
  std::string dir;
  if (resuming) {
    dir = fs::absolute(*args.resume).lexically_normal().string();
    spec = read_study_record(dir);
    check_study_against_scene(spec);  // the scene may have changed since
  } else {
    spec = load_study(args.study);
    dir = fs::absolute(args.out ? *args.out : (fs::path("results") / spec.name).string()).lexically_normal().string();
    check_new_study_folder(dir);
  }
  if (args.on == "slurm") require_slurm_commands();
  const std::vector<int> todo = cases_to_run(spec, dir);  // a new study's folder holds none yet
  if (!resuming) {
    fs::create_directories(fs::path(dir) / "cases");
    write_study_record(dir, spec);
  }
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::fprintf(stderr, "fabform: study %s, %zu cases (%zu to run) on %s, in %s\n", spec.name.c_str(), spec.cases.size(),
               todo.size(), args.on.c_str(), dir.c_str());
  const InterruptHandlers handlers;
  StudyProgress progress(stderr, static_cast<int>(todo.size()), static_cast<int>(spec.cases.size()), args.quiet);
  CaseEndings endings;
  if (args.on == "slurm") {
    const SlurmOptions options{args.partition, args.time_limit_min, args.mem_mb, std::max(1, args.threads_per_case), args.jobs};
    endings = run_on_slurm(spec, dir, todo, options, progress);
  } else {
    const int jobs = args.jobs > 0 ? args.jobs : cores;
    const int threads = args.threads_per_case > 0 ? args.threads_per_case : threads_per_case(cores, jobs);
    endings = run_local_pool(spec, dir, todo, {jobs, threads}, progress);
  }
  progress.finish();
  const int converged = write_study_table(spec, dir, endings);
  if (spec.specimens > 1) write_specimen_summary(spec, dir, endings);
  write_report(dir);
  const int cases = static_cast<int>(spec.cases.size());
  std::fprintf(stderr, "fabform: study %s: %d of %d cases converged; table %s/study.csv%s, report %s/study.html\n",
               spec.name.c_str(), converged, cases, dir.c_str(),
               spec.specimens > 1 ? (", specimens' means " + dir + "/study_specimens.csv").c_str() : "", dir.c_str());
  if (interrupt_signal() != 0) {
    std::fprintf(stderr, "fabform: interrupted; go on with: fabform study --resume %s\n", dir.c_str());
    return kExitInterruptedBase + interrupt_signal();
  }
  if (converged < cases && !cases_to_run(spec, dir).empty())
    std::fprintf(stderr, "fabform: some cases have no result; redo them with: fabform study --resume %s\n", dir.c_str());
  return converged == cases ? kExitDone : kExitNotConverged;
}

}  // namespace

Command add_study_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("study", "run every case of a study, here or on Slurm, and tabulate them");
  command->add_option("STUDY", "the study file (TOML; docs/studies.md)");
  command->add_option("--out", "the study's folder, new or empty")->type_name("DIR");
  command->add_option("--resume", "go on with a study's folder: its cases without a result")->type_name("DIR");
  command->add_option("--on", "where the cases run: local (default) or slurm")->type_name("local|slurm");
  command->add_option("--jobs", "cases at once (default: local, one per core; Slurm, no throttle)")->type_name("J");
  command->add_option("--threads-per-case", "threads each case solves with")->type_name("T");
  command->add_option("--partition", "Slurm's partition")->type_name("P");
  command->add_option("--time-limit", "Slurm's time limit per case, minutes")->type_name("MIN");
  command->add_option("--mem-mb", "Slurm's memory per case, MB")->type_name("M");
  command->add_flag("--quiet", "no progress lines");
  command->allow_extras();
  auto args = std::make_shared<StudyArguments>();
  return {command, [command, args] { *args = read_study_arguments(*command); }, [args] { return study(*args); }};
}

}  // namespace fabform::cli
