#pragma once
// The processes a study starts: this very binary for each case, and the tools it calls
// (Slurm's commands, the report script). Arguments go to execvp as they are: no shell.
#include <sys/types.h>

#include <string>
#include <vector>

namespace fabform {

/// The running fabform binary (/proc/self/exe), so cases run the same build as the study.
std::string self_executable();

/// Whether `name` is an executable file in a folder of $PATH.
bool on_path(const std::string& name);

/// Starts argv (argv[0] looked up on $PATH) in a process group of its own, so a Ctrl-C on the
/// study's terminal reaches the study alone, which then asks each case once to stop. Its
/// standard output and error go to `log`. Returns its process id; throws SystemError
/// when it cannot fork.
pid_t start_process(const std::vector<std::string>& argv, const std::string& log);

struct CommandOutput {
  int status = -1;  // exit status; 128 + the signal when one killed it; 127 when it could not start
  std::string out;
  std::string err;
};

/// Runs argv to its end and collects what it printed.
CommandOutput run_process(const std::vector<std::string>& argv);

/// The status waitpid reports, as a shell says it: the exit status, or 128 + the signal.
int exit_status_of(int wait_status);

}  // namespace fabform
