#pragma once
// Reads a study file (TOML; the format is in studies/README.md) and checks it against its base
// scene before any case runs: every value is applied to the scene as `fabform run --set` would
// apply it and the scene read, so a key the scene lacks or a value it refuses is reported with
// the study file's line; every figure must be one that the cases' result.json files will hold.
#include <string>
#include <string_view>

#include "fabform/study/study_spec.hpp"

namespace fabform {

/// Reads and validates a study. Throws InputError naming the study file, the line and the key
/// (or the scene file, when the base scene itself is wrong).
StudySpec load_study(const std::string& path);

/// The same for a study's text; `path` names it in errors and places its base scene, as
/// load_study's file would.
StudySpec parse_study(std::string_view text, const std::string& path);

/// Checks every case of a study against its base scene, as load_study does (and --resume
/// again, as the scene may have changed since).
void check_study_against_scene(const StudySpec& spec);

}  // namespace fabform
