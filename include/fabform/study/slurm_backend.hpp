#pragma once
// Runs a study's cases on a Slurm cluster: one job array (DIR/slurm/study.sbatch, a task per
// case, each the same `fabform run` the local pool starts), submitted with sbatch and followed
// with squeue, then scontrol for how a task ended that left no finished result (accounting,
// which sacct needs, is not assumed). The study folder must be on a file system the compute
// nodes share, as the binary and the scene must.
#include <string>
#include <vector>

#include "fabform/study/study_progress.hpp"
#include "fabform/study/study_spec.hpp"
#include "fabform/study/study_table.hpp"

namespace fabform {

/// sbatch's own flags: --partition, --time (minutes), --mem (MB), --cpus-per-task, and the
/// array's throttle (%J: at most J tasks at once). 0 or "" leaves sbatch's default.
struct SlurmOptions {
  std::string partition;
  int time_limit_min = 0;
  int mem_mb = 0;
  int threads = 1;
  int jobs = 0;
};

/// Throws InputError when Slurm's commands (sbatch, squeue, scontrol, scancel) are not on $PATH.
void require_slurm_commands();

/// The job-array script that runs the cases `todo` with `binary`.
std::string slurm_script(const StudySpec& spec, const std::string& dir, const std::vector<int>& todo,
                         const SlurmOptions& options, const std::string& binary);

/// Writes the script, submits it and follows its tasks to their end; returns how the cases
/// that left no finished result ended (cancelled, timeout, failed). An interrupt to the study
/// cancels the job. Throws SystemError with sbatch's message when it refuses the job.
CaseEndings run_on_slurm(const StudySpec& spec, const std::string& dir, const std::vector<int>& todo,
                         const SlurmOptions& options, StudyProgress& progress);

}  // namespace fabform
