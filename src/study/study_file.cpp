#include "fabform/study/study_file.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <toml++/toml.h>

#include "fabform/scene/scene_toml.hpp"
#include "fabform/study/result_figures.hpp"
#include "fabform/study/study_cases.hpp"
#include "scene/toml_table_reader.hpp"

namespace fabform {
namespace {

namespace fs = std::filesystem;

SourceLocation at(const std::string& file, const toml::node& node, const std::string& key) {
  return {file, static_cast<int>(node.source().begin.line), key};
}

// The shortest text that reads back as the same double (toml++ writes 17 digits: 1e-5 would
// show as 1.0000000000000001e-05), kept a float for TOML.
std::string float_text(double value) {
  char text[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  std::string out = text;
  return out.find_first_of(".eni") == std::string::npos ? out + ".0" : out;
}

std::string toml_text(const toml::node& node) {
  if (node.is_floating_point()) return float_text(*node.value<double>());
  if (const toml::array* array = node.as_array()) {
    std::string out = "[";
    for (const toml::node& element : *array) out += (out.size() > 1 ? ", " : "") + toml_text(element);
    return out + "]";
  }
  std::ostringstream out;
  node.visit([&](const auto& n) { out << n; });
  return out.str();
}

StudyValue study_value(const std::string& file, const std::string& key, const toml::node& node) {
  const std::string toml = toml_text(node);
  return {key, toml, node.is_string() ? *node.value<std::string>() : toml, at(file, node, key)};
}

// The dotted keys under a table and their nodes: "solver.name" may be written quoted or as
// TOML's own dotted key (a nested table); both mean the scene key solver.name.
void flatten(const toml::table& table, const std::string& prefix, std::vector<std::pair<std::string, const toml::node*>>* out) {
  for (auto&& [k, node] : table) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* inner = node.as_table(); inner && !inner->is_inline()) flatten(*inner, key, out);
    else out->emplace_back(key, &node);
  }
}

// In the order written (toml++ keeps a table's keys sorted): the columns follow the file.
std::vector<std::pair<std::string, const toml::node*>> flattened(const toml::node* node) {
  std::vector<std::pair<std::string, const toml::node*>> out;
  if (node && node->as_table()) flatten(*node->as_table(), "", &out);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    const toml::source_position pa = a.second->source().begin, pb = b.second->source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  });
  return out;
}

std::vector<StudyAxis> grid_axes(const std::string& file, const toml::node& grid) {
  std::vector<StudyAxis> axes;
  for (const auto& [key, node] : flattened(&grid)) {
    const toml::array* values = node->as_array();
    if (!values) throw InputError(at(file, *node, key), "must be a list of values: [a, b, ...]");
    if (values->empty()) throw InputError(at(file, *node, key), "empty list of values: give at least one");
    StudyAxis axis{key, {}};
    for (const toml::node& v : *values) axis.values.push_back(study_value(file, key, v));
    axes.push_back(std::move(axis));
  }
  if (axes.empty()) throw InputError(at(file, grid, "grid"), "no key to vary");
  return axes;
}

std::vector<StudyCase> listed_cases(const std::string& file, const toml::node& list, std::vector<std::string>* keys) {
  const toml::array* tables = list.as_array();
  if (!tables || !tables->is_array_of_tables()) throw InputError(at(file, list, "case"), "must be tables: [[case]]");
  std::vector<StudyCase> cases;
  for (std::size_t i = 0; i < tables->size(); ++i) {
    const toml::node& table = (*tables)[i];
    const std::string where = "case." + std::to_string(i);
    std::vector<std::string> these;
    StudyCase c;
    for (const auto& [key, node] : flattened(&table)) {
      these.push_back(key);
      c.values.push_back(study_value(file, key, *node));
    }
    if (these.empty()) throw InputError(at(file, table, where), "a case sets no value");
    if (i == 0) *keys = these;
    std::vector<std::string> sorted_these = these, sorted_keys = *keys;
    std::sort(sorted_these.begin(), sorted_these.end());
    std::sort(sorted_keys.begin(), sorted_keys.end());
    if (sorted_these != sorted_keys)
      throw InputError(at(file, table, where), "every case must set the same keys as the first one (the table's columns)");
    // In the first case's order, so that every row's values line up with the columns.
    std::vector<StudyValue> ordered;
    for (const std::string& k : *keys)
      ordered.push_back(*std::find_if(c.values.begin(), c.values.end(), [&](const StudyValue& v) { return v.key == k; }));
    cases.push_back({std::move(ordered)});
  }
  return cases;
}

std::vector<StudyCase> sampled_cases(const std::string& file, TableReader sample, const toml::table& raw) {
  const long long count = sample.integer("count", 0, true);
  if (count < 1 || count > 100000) sample.fail("count", "must be between 1 and 100000");
  if (!sample.has("seed")) sample.fail("seed", "missing: a sample needs a seed (an integer) so that it can be drawn again");
  const long long seed = sample.integer("seed", 0, true);
  if (seed < 0) sample.fail("seed", "must be 0 or more");
  sample.take("ranges");
  sample.reject_unknown({"count", "seed", "ranges"});
  std::vector<SampleRange> ranges;
  for (const auto& [key, node] : flattened(raw.get("ranges"))) {
    const toml::array* pair = node->as_array();
    const auto number = [&](std::size_t i) { return (*pair)[i].is_number() ? (*pair)[i].value<double>() : std::nullopt; };
    if (!pair || pair->size() != 2 || !number(0) || !number(1) || !(*number(0) <= *number(1)))
      throw InputError(at(file, *node, key), "must be a range [low, high] of two numbers, low ≤ high");
    ranges.push_back({key, *number(0), *number(1), (*pair)[0].is_integer() && (*pair)[1].is_integer(), at(file, *node, key)});
  }
  if (ranges.empty()) sample.fail("ranges", "missing: [sample.ranges] gives each sampled key its range [low, high]");
  return latin_hypercube(ranges, static_cast<int>(count), static_cast<std::uint64_t>(seed));
}

std::vector<std::string> figure_paths(const std::string& file, TableReader& study, const toml::node* node,
                                      std::vector<SourceLocation>* where) {
  std::vector<std::string> paths;
  study.take("figures");
  if (!node) return paths;
  const toml::array* list = node->as_array();
  if (!list) study.fail("figures", "must be a list of result.json paths: [\"figures.max_warp_strain\", ...]");
  for (const toml::node& f : *list) {
    if (!f.is_string()) throw InputError(at(file, f, "study.figures"), "must be a list of strings");
    paths.push_back(*f.value<std::string>());
    where->push_back(at(file, f, "study.figures"));
  }
  return paths;
}

std::vector<SceneOverride> overrides_of(const std::vector<StudyValue>& values) {
  std::vector<SceneOverride> overrides;
  for (const StudyValue& v : values) overrides.push_back({v.key, v.toml});
  return overrides;
}

// A scene error caused by a study value is the study's: it names the study file's line and the
// value's key (the error from the scene itself names the scene file and stays so).
Scene scene_with(const StudySpec& spec, const std::vector<StudyValue>& values, const StudyValue& blamed) {
  try {
    return load_scene(spec.scene, overrides_of(values));
  } catch (const InputError& error) {
    if (error.where().file != kOverrideSource) throw;
    const std::string& key = error.where().key;
    auto culprit = std::find_if(values.begin(), values.end(), [&](const StudyValue& v) {
      return key == v.key || key.rfind(v.key + ".", 0) == 0 || v.key.rfind(key + ".", 0) == 0;
    });
    const StudyValue& v = culprit != values.end() ? *culprit : blamed;
    const std::string said = key == v.key ? error.message() : key + ": " + error.message();
    throw InputError(v.where, said + " (in the base scene " + spec.scene + ")");
  }
}

// Each case becomes its specimens, the seed their last column; a study that sets the seed itself
// would run one specimen N times.
void with_specimens(StudySpec* spec) {
  std::vector<StudyValue> given = spec->fixed;
  if (!spec->cases.empty()) given.insert(given.end(), spec->cases.front().values.begin(), spec->cases.front().values.end());
  for (const StudyValue& v : given)
    if (v.key == kSpecimenSeedKey)
      throw InputError(v.where, "is the specimens' own: with specimens = " + std::to_string(spec->specimens) +
                                    " the k-th specimen of every case runs with initial.seed = k");
  spec->cases = specimen_cases(spec->cases, spec->specimens, spec->specimens_where);
  spec->varied.push_back(kSpecimenSeedKey);
}

// Specimens differ only by what the seed draws: the start's imperfection or a jittered mesh.
void check_specimens_differ(const StudySpec& spec, const Scene& scene) {
  if (spec.specimens < 2 || scene.perturbation.amplitude_m > 0.0 || scene.fabric.mesh == FabricSpec::Mesh::jittered) return;
  throw InputError(spec.specimens_where,
                   "every specimen would be the same run: the scene's start has no imperfection (initial.perturbation_m "
                   "is 0) and its mesh is not jittered, and the seed draws nothing else");
}

}  // namespace

void check_study_against_scene(const StudySpec& spec) {
  const StudyValue none{"", "", "", {spec.file, 0, ""}};
  scene_with(spec, spec.fixed, spec.fixed.empty() ? none : spec.fixed.front());
  std::map<std::pair<std::string, std::string>, bool> seen;
  for (const StudyCase& c : spec.cases)
    for (const StudyValue& v : c.values)
      if (!seen[{v.key, v.toml}]) {
        seen[{v.key, v.toml}] = true;
        std::vector<StudyValue> alone = spec.fixed;
        alone.push_back(v);
        scene_with(spec, alone, v);
      }
  for (const StudyCase& c : spec.cases) {
    std::vector<StudyValue> all = spec.fixed;
    all.insert(all.end(), c.values.begin(), c.values.end());
    const Scene scene = scene_with(spec, all, c.values.front());
    check_specimens_differ(spec, scene);
    const std::vector<std::string> known = result_figure_paths(scene);
    for (std::size_t i = 0; i < spec.figures.size(); ++i)
      if (std::find(known.begin(), known.end(), spec.figures[i]) == known.end()) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        const SourceLocation where =
            i < spec.figure_where.size() ? spec.figure_where[i] : SourceLocation{spec.file, 0, "study.figures"};
        throw InputError(where, "'" + shown(spec.figures[i]) + "' is a figure no result of this study has (its results have: " +
                                    list + ")");
      }
  }
}

StudySpec load_study(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError({path, 0, ""}, "no such study file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw InputError({path, 0, ""}, "cannot be read");
  return parse_study(text.str(), path);
}

StudySpec parse_study(std::string_view text, const std::string& path) {
  toml::table root;
  try {
    root = toml::parse(text, std::string_view(path));
  } catch (const toml::parse_error& error) {
    throw InputError({path, static_cast<int>(error.source().begin.line), ""}, std::string(error.description()));
  }
  const OverriddenKeys none;
  TableReader top(&root, "", path, none);
  TableReader study = top.table("study", true);
  StudySpec spec;
  spec.file = path;
  spec.name = study.text("name", fs::path(path).stem().string());
  const std::string scene = study.text("scene", "", true);
  spec.scene = fs::absolute(fs::path(path).parent_path() / scene).lexically_normal().string();
  study.text("description", "");
  spec.figures = figure_paths(path, study, root["study"]["figures"].node(), &spec.figure_where);
  const toml::node* set = study.take("set");
  if (set && !set->is_table()) study.fail("set", "must be a table of scene values: [study.set]");
  for (const auto& [key, node] : flattened(set)) spec.fixed.push_back(study_value(path, key, *node));
  const long long specimens_given = study.integer("specimens", 1);
  if (specimens_given < 1 || specimens_given > kMaxSpecimens)
    study.fail("specimens", "must be between 1 and " + std::to_string(kMaxSpecimens));
  spec.specimens = static_cast<int>(specimens_given);
  const toml::node* specimens = root["study"]["specimens"].node();
  spec.specimens_where = specimens ? at(path, *specimens, "study.specimens") : SourceLocation{path, 0, "study.specimens"};
  study.reject_unknown({"name", "scene", "description", "figures", "set", "specimens"});

  const int kinds = (root.contains("grid") ? 1 : 0) + (root.contains("case") ? 1 : 0) + (root.contains("sample") ? 1 : 0);
  if (kinds > 1 || (kinds == 0 && spec.specimens == 1))
    top.fail(kinds == 0 ? "grid" : "case", "a study gives its cases one way: a [grid], a list of [[case]] or a [sample]");
  if (kinds == 0) {
    spec.cases.emplace_back();  // the base scene's own specimens
  } else if (const toml::node* grid = top.take("grid")) {
    const std::vector<StudyAxis> axes = grid_axes(path, *grid);
    for (const StudyAxis& a : axes) spec.varied.push_back(a.key);
    spec.cases = grid_cases(axes);
  } else if (const toml::node* list = top.take("case")) {
    spec.cases = listed_cases(path, *list, &spec.varied);
  } else {
    const toml::table* raw = root["sample"].as_table();
    if (!raw) top.fail("sample", "must be a table");
    spec.cases = sampled_cases(path, top.table("sample", true), *raw);
    for (const StudyValue& v : spec.cases.front().values) spec.varied.push_back(v.key);
  }
  top.reject_unknown({"study", "grid", "case", "sample"});
  for (const StudyValue& f : spec.fixed)
    if (std::find(spec.varied.begin(), spec.varied.end(), f.key) != spec.varied.end())
      throw InputError(f.where, "is both set for every case and varied");
  if (spec.specimens > 1) with_specimens(&spec);
  for (std::size_t i = 0; i < spec.figures.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (spec.figures[i] == spec.figures[j])
        throw InputError(spec.figure_where[i], "'" + shown(spec.figures[i]) + "' is listed twice");
  check_study_against_scene(spec);
  return spec;
}

}  // namespace fabform
