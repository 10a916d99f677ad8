#include "scene/scene_overrides.hpp"

#include <sstream>

namespace fabform {
namespace {

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream stream(key);
  std::string part;
  while (std::getline(stream, part, '.')) parts.push_back(part);
  return parts;
}

toml::table parse_override_value(const SceneOverride& o) {
  const auto attempt = [&](const std::string& value) {
    return toml::parse("v = " + value, std::string_view(kOverrideSource));
  };
  try {
    return attempt(o.value);
  } catch (const toml::parse_error&) {
    std::string quoted = "'" + o.value + "'";
    if (o.value.find('\'') != std::string::npos || o.value.find('\n') != std::string::npos)
      throw InputError({kOverrideSource, 0, o.key}, "value is neither TOML nor a plain string");
    return attempt(quoted);
  }
}

void apply_override(toml::table& root, const SceneOverride& o) {
  const auto parts = split_key(o.key);
  const auto bad = [&](const std::string& why) {
    return InputError({kOverrideSource, 0, o.key}, why);
  };
  for (const auto& p : parts)
    if (p.empty()) throw bad("empty part in the dotted key");
  toml::node* current = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (auto* table = current->as_table()) {
      if (!table->get(parts[i])) table->insert(parts[i], toml::table{});
      current = table->get(parts[i]);
    } else if (auto* array = current->as_array()) {
      std::size_t index = 0;
      try {
        index = std::stoul(parts[i]);
      } catch (const std::exception&) {
        throw bad("'" + parts[i] + "' must be an array index");
      }
      if (index >= array->size()) throw bad("index " + parts[i] + " is out of range");
      current = array->get(index);
    } else {
      throw bad("'" + parts[i] + "' is not a table");
    }
  }
  auto* target = current->as_table();
  if (!target) throw bad("cannot set a value inside a non-table");
  toml::table value = parse_override_value(o);
  value.get("v")->visit([&](auto& node) { target->insert_or_assign(parts.back(), node); });
}

}  // namespace

SceneOverride parse_override(const std::string& argument) {
  const auto equals = argument.find('=');
  if (equals == std::string::npos || equals == 0)
    throw InputError({kOverrideSource, 0, argument}, "expected KEY=VALUE");
  return {argument.substr(0, equals), argument.substr(equals + 1)};
}

OverriddenKeys apply_overrides(toml::table& root, const std::vector<SceneOverride>& overrides) {
  OverriddenKeys overridden;
  for (const auto& o : overrides) {
    apply_override(root, o);
    overridden.insert(o.key);
  }
  return overridden;
}

}  // namespace fabform
