#include "fabform/study/local_pool.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <map>
#include <thread>

#include "fabform/solver/interrupt.hpp"
#include "fabform/study/child_process.hpp"
#include "fabform/study/study_case.hpp"

namespace fabform {

int threads_per_case(int cores, int jobs) { return std::max(1, cores / std::max(1, jobs)); }

CaseEndings run_local_pool(const StudySpec& spec, const std::string& dir, const std::vector<int>& todo,
                           const LocalPoolOptions& options, StudyProgress& progress) {
  namespace fs = std::filesystem;
  fs::create_directories(fs::path(dir) / "logs");
  const std::string binary = self_executable();
  std::map<pid_t, int> running;  // process → case
  CaseEndings endings;
  std::size_t next = 0;
  int done = 0, failed = 0;
  bool stopping = false;
  while ((!stopping && next < todo.size()) || !running.empty()) {
    if (interrupt_signal() != 0 && !stopping) {
      stopping = true;
      for (const auto& [pid, index] : running) kill(pid, SIGTERM);
    }
    while (!stopping && next < todo.size() && static_cast<int>(running.size()) < options.jobs) {
      const int index = todo[next++];
      std::vector<std::string> argv = {binary};
      for (std::string& a : case_arguments(spec, dir, index, options.threads)) argv.push_back(std::move(a));
      const std::string log = (fs::path(dir) / "logs" / (fs::path(case_folder(dir, index)).filename().string() + ".log")).string();
      running[start_process(argv, log)] = index;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid <= 0) {
      progress.update(done, static_cast<int>(running.size()), failed);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const int index = it->second;
    running.erase(it);
    ++done;
    const std::string folder = case_folder(dir, index);
    const std::string termination = case_termination(folder);
    if (case_state(folder) != CaseState::finished)
      endings[index] = termination == "interrupted" ? "interrupted" : "failed";
    if (termination != "converged") ++failed;
    progress.update(done, static_cast<int>(running.size()), failed);
  }
  return endings;
}

}  // namespace fabform
