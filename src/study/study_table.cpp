#include "fabform/study/study_table.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fabform/output/atomic_file.hpp"
#include "fabform/study/result_figures.hpp"
#include "fabform/study/study_case.hpp"

namespace fabform {

std::string number_cell(const nlohmann::json& value) {
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (!value.is_number()) return "";
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value.get<double>());
  return text;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

nlohmann::json case_result(const std::string& dir, int index, const CaseEndings& endings) {
  return endings.count(index) ? nlohmann::json() : finished_result(case_folder(dir, index));
}

std::string study_table(const StudySpec& spec, const std::string& dir, const CaseEndings& endings) {
  std::ostringstream out;
  out << "case";
  for (const std::string& key : spec.varied) out << ',' << csv_cell(key);
  for (const std::string& figure : spec.figures) out << ',' << csv_cell(figure);
  out << ",converged,termination,iterations,wall_seconds\n";
  for (int i = 0; i < static_cast<int>(spec.cases.size()); ++i) {
    out << i;
    for (const StudyValue& v : spec.cases[static_cast<std::size_t>(i)].values) out << ',' << csv_cell(v.text);
    const nlohmann::json result = case_result(dir, i, endings);
    const bool finished = !result.is_null();
    for (const std::string& figure : spec.figures) {
      const nlohmann::json::json_pointer pointer(figure_pointer(figure));
      out << ',' << (finished && result.contains(pointer) ? number_cell(result[pointer]) : "");
    }
    if (finished) {
      out << ',' << number_cell(result.value("converged", false)) << ',' << csv_cell(result.value("termination", ""))
          << ',' << number_cell(result.value("iterations", nlohmann::json())) << ','
          << number_cell(result.value("wall_seconds", nlohmann::json())) << '\n';
    } else {
      const auto ending = endings.find(i);
      out << ",false," << csv_cell(ending != endings.end() ? ending->second : "missing") << ",,\n";
    }
  }
  return out.str();
}

int write_study_table(const StudySpec& spec, const std::string& dir, const CaseEndings& endings) {
  const std::string text = study_table(spec, dir, endings);
  write_file_atomically((std::filesystem::path(dir) / "study.csv").string(), text);
  int converged = 0;
  for (int i = 0; i < static_cast<int>(spec.cases.size()); ++i)
    if (const nlohmann::json result = case_result(dir, i, endings); !result.is_null() && result.value("converged", false))
      ++converged;
  return converged;
}

}  // namespace fabform
