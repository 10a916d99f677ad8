#pragma once
// Runs the real fabform binary in a test's scratch folder and collects what it said.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::test {

struct Outcome {
  int status = -1;  // the exit status; -1 when the process died of a signal
  std::string out;
  std::string err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs `fabform ARGUMENTS` inside dir.
inline Outcome run_fabform(const TempDir& dir, const std::string& arguments) {
  const std::string command = "cd '" + dir.root().string() + "' && '" + fabform_binary() + "' " + arguments +
                              " >stdout.txt 2>stderr.txt";
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir.path("stdout.txt")), slurp(dir.path("stderr.txt"))};
}

/// Starts `fabform ARGUMENTS...` inside dir without waiting (its stdout and stderr go to
/// stdout.txt and stderr.txt there); returns its process id.
inline pid_t start_fabform(const TempDir& dir, const std::vector<std::string>& arguments) {
  const std::string binary = fabform_binary();
  std::vector<std::string> words = {binary};
  words.insert(words.end(), arguments.begin(), arguments.end());
  const pid_t pid = fork();
  if (pid != 0) return pid;
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  if (chdir(dir.root().c_str()) != 0) _exit(127);
  dup2(open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
  dup2(open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
  execv(binary.c_str(), argv.data());
  _exit(127);
}

/// Waits for a process started by start_fabform: its exit status, or -signal if a signal killed it.
inline int wait_for_exit(pid_t pid) {
  int raw = 0;
  waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -WTERMSIG(raw);
}

inline int line_count(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

/// The lines of an error on stderr: all of them, or, after a usage error, those before the
/// command's usage that follows it (its one-line description, then "Usage: fabform ...").
inline int error_line_count(const std::string& err) {
  const std::size_t usage = err.find("\nUsage: fabform");
  if (usage == std::string::npos) return line_count(err);
  const std::size_t description = err.rfind('\n', usage - 1);
  return line_count(err.substr(0, description == std::string::npos ? 0 : description + 1));
}

}  // namespace fabform::test
