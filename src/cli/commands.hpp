#pragma once
// The fabform command line (CLI11): one subcommand per command, each returning the exit status
// (0 done, 2 bad input or usage, 3 did not converge, 4 numerical failure, 5 the system refused
// (a full disk, a missing permission, memory), 70 an internal error, a bug (sysexits' EX_SOFTWARE),
// 128 + the signal's number when SIGINT or SIGTERM interrupted a run, as shells report a signal).
#include <functional>
#include <string>
#include <vector>

#include "fabform/error.hpp"

namespace CLI {
class App;
}

namespace fabform::cli {

constexpr int kExitDone = 0;
constexpr int kExitBadInput = 2;
constexpr int kExitNotConverged = 3;
constexpr int kExitNumericalFailure = 4;
constexpr int kExitSystemRefused = 5;
constexpr int kExitInternalError = 70;
constexpr int kExitInterruptedBase = 128;

/// A command on the command line: `read` checks what CLI11 parsed into its options (throwing an
/// InputError on "command line" that names the option), `run` does the command and returns its
/// exit status. Each is run under guarded().
struct Command {
  CLI::App* options = nullptr;  // its subcommand, for its help
  std::function<void()> read;
  std::function<int()> run;
};

/// Each command adds its subcommand, options and help to the command line.
Command add_run_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_study_command(CLI::App& app);
Command add_predistort_command(CLI::App& app);

/// What a command's subcommand left unparsed: an option it does not know is refused by name,
/// a second positional argument with `why`.
void refuse_leftovers(const CLI::App& command, const std::string& why);

/// A usage error: the option (or the argument's name) and what is wrong with it.
InputError usage_error(const std::string& option, const std::string& why);

/// Every value the command line gave an option, in order (none when it was not given).
const std::vector<std::string>& values_of(const CLI::App& command, const std::string& option);

/// The last value the command line gave an option, or null when it gave none.
const std::string* given(const CLI::App& command, const std::string& option);

}  // namespace fabform::cli
