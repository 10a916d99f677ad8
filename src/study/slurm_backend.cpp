#include "fabform/study/slurm_backend.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "fabform/error.hpp"
#include "fabform/output/atomic_file.hpp"
#include "fabform/solver/interrupt.hpp"
#include "fabform/study/child_process.hpp"
#include "fabform/study/study_case.hpp"

namespace fabform {
namespace {

namespace fs = std::filesystem;

// A word for sh: single-quoted, its own quotes closed and escaped.
std::string quoted(const std::string& word) {
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// The tasks of the job still in the queue (pending, running, completing) and how many run.
struct Queue {
  std::set<int> listed;
  int running = 0;
  bool known = true;  // false: squeue failed for another reason than the job having left
};

Queue queue_of(const std::string& job) {
  const CommandOutput q = run_process({"squeue", "-h", "-r", "-j", job, "-o", "%K %T"});
  Queue queue;
  if (q.status != 0) {
    // Once every task has left the queue, squeue may call the job id invalid: nothing is queued.
    queue.known = q.err.find("Invalid job id") != std::string::npos;
    return queue;
  }
  std::istringstream lines(q.out);
  std::string task, state;
  while (lines >> task >> state) {
    if (task.find_first_not_of("0123456789") != std::string::npos) continue;  // a range not yet split
    queue.listed.insert(std::stoi(task));
    if (state == "RUNNING" || state == "COMPLETING") ++queue.running;
  }
  return queue;
}

// How a task that left the queue ended, from the controller's records of the job: its own
// record's state, or "" while it is still going. A pending task cancelled leaves no record of its
// own (it is only taken out of the array's pending set): a task the known job has no record of
// was cancelled.
std::string task_ending(const std::string& job, int index) {
  const CommandOutput s = run_process({"scontrol", "show", "job", "-o", job});
  if (s.status != 0) return "failed";
  std::istringstream records(s.out);
  for (std::string record; std::getline(records, record);) {
    const auto task = record.find(" ArrayTaskId=" + std::to_string(index) + " ");
    const auto at = record.find(" JobState=");
    if (task == std::string::npos || at == std::string::npos) continue;
    const std::string state = record.substr(at + 10, record.find(' ', at + 10) - at - 10);
    if (state == "PENDING" || state == "RUNNING" || state == "CONFIGURING" || state == "COMPLETING" ||
        state == "SUSPENDED" || state == "REQUEUED")
      return "";
    if (state == "CANCELLED") return "cancelled";
    if (state == "TIMEOUT" || state == "DEADLINE") return "timeout";
    if (state == "OUT_OF_MEMORY") return "out of memory";
    return "failed";
  }
  return "cancelled";
}

}  // namespace

void require_slurm_commands() {
  for (const char* command : {"sbatch", "squeue", "scontrol", "scancel"})
    if (!on_path(command))
      throw InputError({"command line", 0, "--on"},
                       std::string("slurm: ") + command + " is not on the PATH (install Slurm's client commands, or run with --on local); nothing submitted");
}

std::string slurm_script(const StudySpec& spec, const std::string& dir, const std::vector<int>& todo,
                         const SlurmOptions& options, const std::string& binary) {
  std::ostringstream s;
  std::string array;
  for (const int index : todo) array += (array.empty() ? "" : ",") + std::to_string(index);
  if (options.jobs > 0) array += "%" + std::to_string(options.jobs);
  s << "#!/bin/sh\n# fabform study " << spec.name << ": one array task per case (written by fabform study)\n"
    << "#SBATCH --job-name=" << quoted("fabform-" + spec.name) << "\n#SBATCH --array=" << array
    << "\n#SBATCH --cpus-per-task=" << options.threads << "\n#SBATCH --chdir=" << quoted(dir)
    << "\n#SBATCH --output=" << quoted((fs::path(dir) / "slurm" / "case-%a.log").string()) << '\n';
  if (!options.partition.empty()) s << "#SBATCH --partition=" << quoted(options.partition) << '\n';
  if (options.time_limit_min > 0) s << "#SBATCH --time=" << options.time_limit_min << '\n';
  if (options.mem_mb > 0) s << "#SBATCH --mem=" << options.mem_mb << '\n';
  s << "case \"$SLURM_ARRAY_TASK_ID\" in\n";
  for (const int index : todo) {
    s << "  " << index << ") exec " << quoted(binary);
    for (const std::string& a : case_arguments(spec, dir, index, options.threads)) s << ' ' << quoted(a);
    s << " ;;\n";
  }
  s << "esac\necho \"fabform study: no case $SLURM_ARRAY_TASK_ID\" >&2\nexit 2\n";
  return s.str();
}

CaseEndings run_on_slurm(const StudySpec& spec, const std::string& dir, const std::vector<int>& todo,
                         const SlurmOptions& options, StudyProgress& progress) {
  const fs::path folder = fs::path(dir) / "slurm";
  fs::create_directories(folder);
  const std::string script = (folder / "study.sbatch").string();
  write_file_atomically(script, slurm_script(spec, dir, todo, options, self_executable()));
  const CommandOutput submitted = run_process({"sbatch", "--parsable", script});
  const std::string job = trimmed(submitted.out.substr(0, submitted.out.find(';')));
  if (submitted.status != 0 || job.empty())
    throw SystemError("sbatch", "queue the study", trimmed(submitted.err));
  std::ofstream(folder / "jobs.txt", std::ios::app) << job << '\n';
  std::fprintf(stderr, "fabform: study %s submitted to Slurm as job %s (%zu tasks)\n", spec.name.c_str(), job.c_str(),
               todo.size());
  CaseEndings endings;
  std::set<int> open(todo.begin(), todo.end());
  int done = 0, failed = 0;
  bool cancelled = false;
  while (!open.empty()) {
    if (interrupt_signal() != 0 && !cancelled) {
      run_process({"scancel", job});
      cancelled = true;
    }
    const Queue queue = queue_of(job);
    if (queue.known)
      for (auto it = open.begin(); it != open.end();) {
        const int index = *it;
        if (queue.listed.count(index)) {
          ++it;
          continue;
        }
        const std::string case_dir = case_folder(dir, index);
        if (case_state(case_dir) != CaseState::finished) {
          const std::string ending = task_ending(job, index);
          if (ending.empty()) {
            ++it;
            continue;
          }
          endings[index] = ending;
        }
        if (case_termination(case_dir) != "converged" || endings.count(index)) ++failed;
        ++done;
        it = open.erase(it);
      }
    progress.update(done, queue.running, failed);
    if (!open.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return endings;
}

}  // namespace fabform
