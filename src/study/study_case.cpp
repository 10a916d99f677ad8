#include "fabform/study/study_case.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fabform {

namespace fs = std::filesystem;

std::string case_folder(const std::string& dir, int index) {
  char name[16];
  std::snprintf(name, sizeof name, "%04d", index);
  return (fs::path(dir) / "cases" / name).string();
}

namespace {

// The folder's result.json, null when it has none or it is not a JSON object.
nlohmann::json result_json(const std::string& folder) {
  std::ifstream in(fs::path(folder) / "result.json", std::ios::binary);
  if (!in) return nullptr;
  nlohmann::json result = nlohmann::json::parse(in, nullptr, false);
  return result.is_object() ? result : nlohmann::json();
}

std::string termination_of(const nlohmann::json& result) {
  if (result.is_null() || !result.contains("termination") || !result["termination"].is_string()) return "";
  return result["termination"].get<std::string>();
}

// A run that ended, whatever its ending; an interrupted or running one has not.
bool ended(const std::string& termination) {
  return !termination.empty() && termination != "interrupted" && termination != "running";
}

}  // namespace

std::string case_termination(const std::string& folder) { return termination_of(result_json(folder)); }

CaseState case_state(const std::string& folder) {
  const std::string termination = case_termination(folder);
  if (termination.empty()) return CaseState::missing;
  if (ended(termination)) return CaseState::finished;
  return fs::exists(fs::path(folder) / "checkpoint.bin") ? CaseState::unfinished : CaseState::missing;
}

nlohmann::json finished_result(const std::string& folder) {
  nlohmann::json result = result_json(folder);  // read once: a study's tables read every case's
  return ended(termination_of(result)) ? result : nlohmann::json();
}

std::vector<std::string> case_arguments(const StudySpec& spec, const std::string& dir, int index, int threads) {
  const std::string folder = case_folder(dir, index);
  if (case_state(folder) == CaseState::unfinished) return {"run", "--resume", folder, "--quiet"};
  std::vector<std::string> args = {"run", spec.scene};
  for (const StudyValue& v : spec.fixed) args.insert(args.end(), {"--set", v.key + "=" + v.toml});
  for (const StudyValue& v : spec.cases[static_cast<std::size_t>(index)].values)
    args.insert(args.end(), {"--set", v.key + "=" + v.toml});
  args.insert(args.end(), {"--out", folder, "--quiet", "--threads", std::to_string(threads)});
  return args;
}

std::vector<int> cases_to_run(const StudySpec& spec, const std::string& dir) {
  std::vector<int> todo;
  for (int i = 0; i < static_cast<int>(spec.cases.size()); ++i)
    if (case_state(case_folder(dir, i)) != CaseState::finished) todo.push_back(i);
  return todo;
}

}  // namespace fabform
