#pragma once
// What a run was made from: the scene file, the overrides of its command line, and the SHA-256
// of every file it read (scene, warp and weft tables, body meshes). result.json records them;
// `fabform run --resume DIR` reads them back to rebuild the same run, and refuses to go on
// when a file has changed since.
#include <string>
#include <vector>

#include "fabform/scene/scene.hpp"
#include "fabform/scene/scene_toml.hpp"

namespace fabform {

struct InputFile {
  std::string role;  // "scene", "warp", "weft", or "body NAME"
  std::string path;
  std::string sha256;
};

struct RunInputs {
  std::string scene_file;  // absolute, so a resume works from any folder
  std::vector<SceneOverride> overrides;
  std::vector<InputFile> files;  // the scene first
};

/// The inputs of a run of `scene`, every file hashed.
RunInputs describe_inputs(const Scene& scene, const std::vector<SceneOverride>& overrides);

/// The inputs an earlier run recorded in its result.json; throws InputError naming the file
/// when it is not a fabform result.json or lacks them.
RunInputs read_run_inputs(const std::string& result_json);

/// How `now` differs from `then` ("the warp table ... has changed"), or "" when not at all.
std::string input_change(const RunInputs& then, const RunInputs& now);

}  // namespace fabform
