#pragma once
// The fabform command line: one function per command, each returning the exit status
// (0 done, 2 bad input or usage, 3 did not converge, 4 numerical failure, 5 the system refused
// (a full disk, a missing permission, memory), 70 an internal error, a bug (sysexits' EX_SOFTWARE),
// 128 + the signal's number when SIGINT or SIGTERM interrupted a run, as shells report a signal).
#include <string>
#include <vector>

namespace fabform::cli {

constexpr int kExitDone = 0;
constexpr int kExitBadInput = 2;
constexpr int kExitNotConverged = 3;
constexpr int kExitNumericalFailure = 4;
constexpr int kExitSystemRefused = 5;
constexpr int kExitInternalError = 70;
constexpr int kExitInterruptedBase = 128;

int run_command(const std::vector<std::string>& args);
int check_command(const std::vector<std::string>& args);
int study_command(const std::vector<std::string>& args);
int predistort_command(const std::vector<std::string>& args);

}  // namespace fabform::cli
