#pragma once
// A study folder's DIR/study.json: the study as it was read (base scene, values set in every
// case, the cases, the figures), so that `fabform study --resume DIR` needs nothing else.
#include <string>

#include "fabform/study/study_spec.hpp"

namespace fabform {

/// Writes DIR/study.json (atomically).
void write_study_record(const std::string& dir, const StudySpec& spec);

/// Reads DIR/study.json. Throws InputError naming the file when it is missing or malformed.
StudySpec read_study_record(const std::string& dir);

/// DIR/study.json's path.
std::string study_record_path(const std::string& dir);

}  // namespace fabform
