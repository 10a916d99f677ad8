#pragma once
// Runs a study's cases on this machine: J cases at once, each an ordinary `fabform run` of this
// very binary with T threads, so that J × T stays within the machine's cores.
#include <string>
#include <vector>

#include "fabform/study/study_progress.hpp"
#include "fabform/study/study_spec.hpp"
#include "fabform/study/study_table.hpp"

namespace fabform {

struct LocalPoolOptions {
  int jobs = 1;     // cases at once
  int threads = 1;  // threads per case
};

/// T for J cases at once on `cores` cores: the cores shared out, at least one each.
int threads_per_case(int cores, int jobs);

/// Runs the cases `todo` (each case's output in DIR/logs/NNNN.log) and returns how those that
/// left no finished result ended. A SIGINT or SIGTERM to the study (fabform/solver/interrupt.hpp)
/// starts no more cases and asks each running one once to stop, so it writes its state.
CaseEndings run_local_pool(const StudySpec& spec, const std::string& dir, const std::vector<int>& todo,
                           const LocalPoolOptions& options, StudyProgress& progress);

}  // namespace fabform
