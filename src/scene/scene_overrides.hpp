#pragma once
// Command-line overrides of scene values (--set KEY=VALUE), applied to the parsed TOML before
// it is read. Internal to the scene parser.
#include <vector>

#include <toml++/toml.h>

#include "fabform/scene/scene_toml.hpp"
#include "scene/toml_table_reader.hpp"

namespace fabform {

/// Applies each override in turn; returns the dotted keys they set. Throws InputError naming
/// the command line for a key that cannot be set.
OverriddenKeys apply_overrides(toml::table& root, const std::vector<SceneOverride>& overrides);

}  // namespace fabform
