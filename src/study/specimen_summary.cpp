#include "fabform/study/specimen_summary.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

#include "fabform/output/atomic_file.hpp"
#include "fabform/study/result_figures.hpp"

namespace fabform {
namespace {

std::string number(double value) { return number_cell(nlohmann::json(value)); }

// Mean, sample standard deviation, least, largest; the deviation needs two readings.
std::string statistics(const std::vector<double>& readings) {
  if (readings.empty()) return ",,,";
  double sum = 0.0;
  for (const double r : readings) sum += r;
  const double mean = sum / static_cast<double>(readings.size());
  double squares = 0.0;
  for (const double r : readings) squares += (r - mean) * (r - mean);
  const std::string sd = readings.size() > 1 ? number(std::sqrt(squares / static_cast<double>(readings.size() - 1))) : "";
  const auto [least, largest] = std::minmax_element(readings.begin(), readings.end());
  return number(mean) + ',' + sd + ',' + number(*least) + ',' + number(*largest);
}

}  // namespace

std::string specimen_summary(const StudySpec& spec, const std::string& dir, const CaseEndings& endings) {
  std::ostringstream out;
  out << "cases";
  const std::size_t shown_keys = spec.varied.empty() ? 0 : spec.varied.size() - 1;  // all but the seed
  for (std::size_t k = 0; k < shown_keys; ++k) out << ',' << csv_cell(spec.varied[k]);
  out << ",specimens,finished,converged";
  for (const std::string& figure : spec.figures)
    for (const char* statistic : {" mean", " sd", " min", " max"}) out << ',' << csv_cell(figure + statistic);
  out << '\n';
  const int per_case = std::max(spec.specimens, 1);
  for (int first = 0; first < static_cast<int>(spec.cases.size()); first += per_case) {
    out << first << '-' << std::min(first + per_case, static_cast<int>(spec.cases.size())) - 1;
    const std::vector<StudyValue>& values = spec.cases[static_cast<std::size_t>(first)].values;
    for (std::size_t k = 0; k < shown_keys && k < values.size(); ++k) out << ',' << csv_cell(values[k].text);
    int finished = 0;
    std::vector<nlohmann::json> converged;
    for (int i = first; i < first + per_case && i < static_cast<int>(spec.cases.size()); ++i) {
      const nlohmann::json result = case_result(dir, i, endings);
      if (result.is_null()) continue;
      ++finished;
      if (result.value("converged", false)) converged.push_back(result);
    }
    out << ',' << per_case << ',' << finished << ',' << converged.size();
    for (const std::string& figure : spec.figures) {
      const nlohmann::json::json_pointer pointer(figure_pointer(figure));
      std::vector<double> readings;
      for (const nlohmann::json& result : converged)
        if (result.contains(pointer) && result[pointer].is_number()) readings.push_back(result[pointer].get<double>());
      out << ',' << statistics(readings);
    }
    out << '\n';
  }
  return out.str();
}

void write_specimen_summary(const StudySpec& spec, const std::string& dir, const CaseEndings& endings) {
  write_file_atomically((std::filesystem::path(dir) / "study_specimens.csv").string(), specimen_summary(spec, dir, endings));
}

}  // namespace fabform
