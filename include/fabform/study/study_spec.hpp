#pragma once
// A parameter study as it runs: a base scene, values set in every case, the cases (each a set
// of scene values by dotted key, as `fabform run --set` takes them) and the result.json figures
// to collect. Read from a study file (study_file.hpp) or from a study folder's study.json
// (study_record.hpp).
#include <string>
#include <vector>

#include "fabform/error.hpp"

namespace fabform {

/// One scene value of a study: its dotted key, the value as TOML text (what `--set` is given),
/// the value as shown in tables (a string without its quotes), and where the study file gave it.
struct StudyValue {
  std::string key;
  std::string toml;
  std::string text;
  SourceLocation where;  // not kept in study.json: only validation reports it
};

/// One case: a value for every varied key, in the order of StudySpec::varied.
struct StudyCase {
  std::vector<StudyValue> values;
};

struct StudySpec {
  std::string file;                // the study file, as given
  std::string name;
  std::string scene;               // the base scene's path, absolute
  std::vector<StudyValue> fixed;   // [study.set]: the same in every case
  std::vector<std::string> varied; // the varied keys: the table's first columns
  std::vector<StudyCase> cases;
  std::vector<std::string> figures;  // result.json paths (result_figures.hpp)
  std::vector<SourceLocation> figure_where;  // where each was listed; not kept in study.json
  // [study] specimens: N > 1 runs every case N times with initial.seed 1 … N (the last varied
  // key), as a tester tests several specimens of one fabric; study_specimens.csv gives each
  // case's mean and scatter (specimen_summary.hpp).
  int specimens = 1;
  SourceLocation specimens_where;  // not kept in study.json
};

}  // namespace fabform
