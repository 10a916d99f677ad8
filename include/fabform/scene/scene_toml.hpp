#pragma once
// Reads a scene file (TOML; the keys are documented in scenes/README.md). Parsing stays here:
// the rest of fabform sees a validated Scene.
#include <string>
#include <string_view>
#include <vector>

#include "fabform/scene/scene.hpp"

namespace fabform {

/// A command-line override: a dotted key (array elements by index, e.g. body.0.scale) and a
/// TOML value; a value that is not valid TOML is taken as a string. `unset` removes the key
/// instead (--unset KEY), so that a scene can switch between keys that exclude each other.
struct SceneOverride {
  std::string key;
  std::string value;
  bool unset = false;
};

/// Parses "KEY=VALUE"; throws InputError naming the argument when there is no '='.
SceneOverride parse_override(const std::string& argument);
/// The override of --unset KEY.
SceneOverride parse_unset(const std::string& key);

/// Parses, overrides and validates scene text; `path` names it in errors and anchors its
/// relative paths.
Scene parse_scene(std::string_view text, const std::string& path,
                  const std::vector<SceneOverride>& overrides = {});

/// Reads, overrides and validates a scene. Throws InputError naming the file, the line and the
/// dotted key of the first problem (or the --set argument that caused it).
Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides = {});

}  // namespace fabform
