#pragma once
// One case of a study on disk: its ordinary run folder DIR/cases/NNNN, whether it holds a
// finished result, and the `fabform run` arguments that make (or finish) it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fabform/study/study_spec.hpp"

namespace fabform {

/// DIR/cases/NNNN (the case's index, from 0, four digits or more).
std::string case_folder(const std::string& dir, int index);

enum class CaseState {
  missing,      // no result: the case runs from the start
  unfinished,   // an interrupted or killed run with its checkpoint: `fabform run --resume` ends it
  finished,     // a result, whatever its termination (converged or not, a numerical failure)
};

CaseState case_state(const std::string& folder);

/// Its result.json when it holds a finished result; null when it does not.
nlohmann::json finished_result(const std::string& folder);

/// The termination its result.json gives ("converged", "not converged", ...), "" without one.
std::string case_termination(const std::string& folder);

/// The arguments after `fabform` that run the case (or resume it, when it is unfinished), with
/// `threads` threads (a resumed run keeps the count it recorded).
std::vector<std::string> case_arguments(const StudySpec& spec, const std::string& dir, int index, int threads);

/// The cases of a study without a finished result, in order.
std::vector<int> cases_to_run(const StudySpec& spec, const std::string& dir);

}  // namespace fabform
