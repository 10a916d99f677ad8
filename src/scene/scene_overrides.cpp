#include "scene/scene_overrides.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace fabform {
namespace {

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream stream(key);
  std::string part;
  while (std::getline(stream, part, '.')) parts.push_back(part);
  if (!key.empty() && key.back() == '.') parts.emplace_back();  // getline drops a trailing empty part
  return parts;
}

// Every scene key is a bare TOML key; anything else (a space, a newline, a quote) is a typo,
// and would otherwise be echoed into a message that must stay one line.
bool is_bare_key(const std::string& part) {
  return !part.empty() && std::all_of(part.begin(), part.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

// Reads digits (with TOML's single underscores between them) from `at`; returns how many.
std::size_t digits_at(const std::string& text, std::size_t* at) {
  std::size_t count = 0;
  while (*at < text.size() && (std::isdigit(static_cast<unsigned char>(text[*at])) ||
                               (count > 0 && text[*at] == '_')))
    count += text[(*at)++] != '_' ? 1 : 0;
  return count;
}

// A well-formed decimal number (sign, digits, fraction, exponent, no leading zero): when TOML
// refuses one, it is out of range ("99999999999999999999", "1e999"), and taking it as a string
// would only say "must be a number". "007" and "1.2.3" stay plain strings.
bool is_decimal_number(const std::string& value) {
  std::size_t at = !value.empty() && (value[0] == '+' || value[0] == '-') ? 1 : 0;
  const std::size_t first = at;
  if (digits_at(value, &at) == 0 || (value[first] == '0' && at - first > 1)) return false;
  if (at < value.size() && value[at] == '.') {
    ++at;
    if (digits_at(value, &at) == 0) return false;
  }
  if (at < value.size() && (value[at] == 'e' || value[at] == 'E')) {
    ++at;
    if (at < value.size() && (value[at] == '+' || value[at] == '-')) ++at;
    if (digits_at(value, &at) == 0) return false;
  }
  return at == value.size();
}

toml::table parse_override_value(const SceneOverride& o) {
  const auto attempt = [&](const std::string& value) {
    return toml::parse("v = " + value, std::string_view(kOverrideSource));
  };
  try {
    return attempt(o.value);
  } catch (const toml::parse_error& error) {
    if (is_decimal_number(o.value))
      throw InputError({kOverrideSource, 0, o.key}, "not a usable number: " + std::string(error.description()));
    std::string quoted = "'" + o.value + "'";
    if (o.value.find('\'') != std::string::npos || o.value.find('\n') != std::string::npos)
      throw InputError({kOverrideSource, 0, o.key}, "value is neither TOML nor a plain string");
    return attempt(quoted);
  }
}

// An array index is digits only: std::stoul alone would read "0x" or " 1" as an index.
std::size_t array_index(const std::string& part, const toml::array& array, const std::string& key) {
  const bool digits = std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits || part.size() > 9)
    throw InputError({kOverrideSource, 0, key}, "'" + part + "' must be an array index");
  const std::size_t index = std::stoul(part);
  if (index >= array.size())
    throw InputError({kOverrideSource, 0, key}, "index " + part + " is out of range");
  return index;
}

// Walks to the table holding the last part, creating missing tables; the dotted keys of the
// tables it created go into `created`, so that what is wrong inside them is blamed on --set.
toml::table& parent_table(toml::table& root, const std::vector<std::string>& parts, const std::string& key,
                          OverriddenKeys* created) {
  toml::node* current = &root;
  std::string dotted;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    dotted += (i == 0 ? "" : ".") + parts[i];
    if (auto* table = current->as_table()) {
      if (!table->get(parts[i])) {
        table->insert(parts[i], toml::table{});
        created->insert(dotted);
      }
      current = table->get(parts[i]);
    } else if (auto* array = current->as_array()) {
      current = array->get(array_index(parts[i], *array, key));
    } else {
      throw InputError({kOverrideSource, 0, key}, "'" + parts[i] + "' is not a table");
    }
  }
  auto* target = current->as_table();
  if (!target) throw InputError({kOverrideSource, 0, key}, "cannot set a value inside a non-table");
  return *target;
}

void apply_override(toml::table& root, const SceneOverride& o, OverriddenKeys* created) {
  const auto parts = split_key(o.key);
  // A study's key reaches here unchecked by parse_override ("" in a [grid], found by fuzzing).
  if (parts.empty()) throw InputError({kOverrideSource, 0, shown(o.key)}, "an empty key names no scene value");
  for (const auto& p : parts)
    if (p.empty()) throw InputError({kOverrideSource, 0, shown(o.key)}, "empty part in the dotted key");
  for (const auto& p : parts)
    if (!is_bare_key(p))
      throw InputError({kOverrideSource, 0, shown(o.key)},
                       "key parts are bare keys: letters, digits, _ and - (e.g. body.0.scale)");
  toml::table& target = parent_table(root, parts, o.key, created);
  if (o.unset) {
    if (!target.erase(parts.back())) throw InputError({kOverrideSource, 0, shown(o.key)}, "--unset: the scene has no such key");
    return;
  }
  toml::table value = parse_override_value(o);
  value.get("v")->visit([&](auto& node) { target.insert_or_assign(parts.back(), node); });
}

}  // namespace

SceneOverride parse_override(const std::string& argument) {
  const auto equals = argument.find('=');
  if (equals == std::string::npos || equals == 0)
    throw InputError({kOverrideSource, 0, shown(argument)}, "expected KEY=VALUE");
  return {argument.substr(0, equals), argument.substr(equals + 1)};
}

SceneOverride parse_unset(const std::string& key) {
  if (key.empty() || key.find('=') != std::string::npos)
    throw InputError({kOverrideSource, 0, shown(key)}, "--unset takes a dotted key alone (e.g. bending.rigidity_Nm)");
  return {key, "", true};
}

OverriddenKeys apply_overrides(toml::table& root, const std::vector<SceneOverride>& overrides) {
  OverriddenKeys overridden;
  for (const auto& o : overrides) {
    apply_override(root, o, &overridden);
    overridden.insert(o.key);
  }
  return overridden;
}

}  // namespace fabform
