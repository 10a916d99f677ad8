#pragma once
// Runs the real fabform binary in a test's scratch folder and collects what it said.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

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

inline int line_count(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace fabform::test
