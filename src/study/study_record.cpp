#include "fabform/study/study_record.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "fabform/output/atomic_file.hpp"
#include "fabform/study/study_cases.hpp"

namespace fabform {
namespace {

nlohmann::json values_json(const std::vector<StudyValue>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (const StudyValue& v : values) out.push_back({{"key", v.key}, {"value", v.toml}, {"text", v.text}});
  return out;
}

std::vector<StudyValue> values_of(const nlohmann::json& list, const std::string& file) {
  std::vector<StudyValue> values;
  for (const auto& v : list)
    values.push_back({v.at("key").get<std::string>(), v.at("value").get<std::string>(), v.at("text").get<std::string>(),
                      {file, 0, v.at("key").get<std::string>()}});
  return values;
}

// A study with specimens groups its cases in runs of `specimens`, the seed varied last and
// counting 1 … specimens within each run, as the study file wrote them.
void check_specimens(const StudySpec& spec) {
  if (spec.specimens == 1) return;
  const auto fail = [&](const std::string& why) {
    throw InputError(spec.specimens_where, "malformed study record: " + why);
  };
  const bool grouped = spec.specimens >= 1 && spec.specimens <= kMaxSpecimens &&
                       spec.cases.size() % static_cast<std::size_t>(spec.specimens) == 0;
  if (!grouped || spec.varied.empty() || spec.varied.back() != kSpecimenSeedKey)
    fail(std::to_string(spec.specimens) + " specimens do not group its " + std::to_string(spec.cases.size()) +
         " cases, or initial.seed is not its last varied key");
  for (std::size_t k = 0; k < spec.cases.size(); ++k) {
    const std::string seed = std::to_string(1 + k % static_cast<std::size_t>(spec.specimens));
    if (spec.cases[k].values.empty() || spec.cases[k].values.back().toml != seed)
      fail("case " + std::to_string(k) + " should be specimen " + seed + " (initial.seed = " + seed + ")");
  }
}

}  // namespace

std::string study_record_path(const std::string& dir) { return (std::filesystem::path(dir) / "study.json").string(); }

void write_study_record(const std::string& dir, const StudySpec& spec) {
  nlohmann::json j;
  j["fabform_version"] = FABFORM_VERSION;
  j["study_file"] = spec.file;
  j["name"] = spec.name;
  j["scene"] = spec.scene;
  j["set"] = values_json(spec.fixed);
  j["varied"] = spec.varied;
  j["figures"] = spec.figures;
  j["specimens"] = spec.specimens;
  nlohmann::json cases = nlohmann::json::array();
  for (const StudyCase& c : spec.cases) cases.push_back(values_json(c.values));
  j["cases"] = cases;
  write_file_atomically(study_record_path(dir), j.dump(2) + "\n");
}

StudySpec read_study_record(const std::string& dir) {
  const std::string path = study_record_path(dir);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, ""}, "no study here (no study.json): start one with fabform study STUDY.toml --out DIR");
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    StudySpec spec;
    spec.file = path;
    spec.name = j.at("name").get<std::string>();
    spec.scene = j.at("scene").get<std::string>();
    spec.fixed = values_of(j.at("set"), path);
    spec.varied = j.at("varied").get<std::vector<std::string>>();
    spec.figures = j.at("figures").get<std::vector<std::string>>();
    spec.specimens = j.value("specimens", 1);  // a record from before specimens has none
    spec.specimens_where = {path, 0, "specimens"};
    for (const auto& c : j.at("cases")) spec.cases.push_back({values_of(c, path)});
    check_specimens(spec);
    return spec;
  } catch (const nlohmann::json::exception& error) {
    throw InputError({path, 0, ""}, std::string("malformed study record: ") + error.what());
  }
}

}  // namespace fabform
