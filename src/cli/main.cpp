#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "fabform/solver/solver_registry.hpp"

namespace {

const char* kUsage =
    "usage: fabform run SCENE [--out DIR] [--solver NAME] [--tol N] [--tol-m METRES]\n"
    "                         [--max-iter K] [--threads T] [--set KEY=VALUE]... [--unset KEY]... [--quiet]\n"
    "       fabform study STUDY.toml [--out DIR] [--jobs J] [--on local|slurm] [--threads-per-case T]\n"
    "                    [--partition P] [--time-limit MIN] [--mem-mb M] [--quiet]\n"
    "       fabform study --resume DIR [--jobs J] [--on local|slurm] ...\n"
    "       fabform check MESH [--units m|cm|mm|in] [--repair OUT.obj]\n"
    "       fabform predistort RESULT_DIR IMAGE.png OUT.png\n"
    "       fabform solvers\n"
    "       fabform --version\n";

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? fabform::cli::kExitBadInput : fabform::cli::kExitDone;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "run") return fabform::cli::run_command(rest);
  if (args[0] == "check") return fabform::cli::check_command(rest);
  if (args[0] == "study") return fabform::cli::study_command(rest);
  if (args[0] == "predistort") return fabform::cli::predistort_command(rest);
  if (args[0] == "solvers" && rest.empty()) {
    for (const auto& solver : fabform::solvers()) std::printf("%s\n", solver.name.c_str());
    return fabform::cli::kExitDone;
  }
  if (args[0] == "--version") {
    std::printf("fabform %s\n", FABFORM_VERSION);
    return fabform::cli::kExitDone;
  }
  std::fprintf(stderr, "fabform: unknown command '%s'\n%s", args[0].c_str(), kUsage);
  return fabform::cli::kExitBadInput;
}
