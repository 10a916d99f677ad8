#pragma once
// Reads one TOML table of a scene: typed values with their dotted key and line for errors,
// and the keys left unread reported as unknown. Internal to the scene parser.
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <toml++/toml.h>

#include "fabform/error.hpp"

namespace fabform {

/// Where values set on the command line are said to come from.
inline const char* const kOverrideSource = "command line --set";

/// A value or key echoed in a message: errors are one line, so control characters are shown
/// escaped (\x0a).
inline std::string shown(const std::string& value) {
  std::string out;
  for (const char c : value) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out += c;
      continue;
    }
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
    out += escaped;
  }
  return out;
}

/// Dotted keys set on the command line; a value there, or inside one, is blamed on it.
using OverriddenKeys = std::set<std::string>;

inline bool is_overridden(const OverriddenKeys& overridden, const std::string& key) {
  for (const auto& o : overridden)
    if (key == o || key.rfind(o + ".", 0) == 0) return true;
  return false;
}

class TableReader {
 public:
  TableReader(const toml::table* table, std::string prefix, std::string file,
              const OverriddenKeys& overridden)
      : table_(table), prefix_(std::move(prefix)), file_(std::move(file)), overridden_(overridden) {}

  SourceLocation locate(const toml::node* node, const std::string& key) const {
    if (is_overridden(overridden_, key)) return {kOverrideSource, 0, key};
    return {file_, node ? static_cast<int>(node->source().begin.line) : 0, key};
  }

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError(locate(node(key) ? node(key) : table_, dotted(key)), message);
  }

  std::string dotted(const std::string& key) const {
    return prefix_.empty() ? key : prefix_ + "." + key;
  }

  bool has(const std::string& key) const { return node(key) != nullptr; }

  const toml::node* take(const std::string& key) {
    used_.insert(key);
    return node(key);
  }

  double number(const std::string& key, double fallback, bool required = false) {
    const toml::node* n = take(key);
    if (!n) {
      if (required) fail(key, "missing (a number is required)");
      return fallback;
    }
    const auto value = n->value<double>();
    if (!value || n->is_boolean()) fail(key, "must be a number");
    if (!std::isfinite(*value)) fail(key, "must be finite");
    return *value;
  }

  bool flag(const std::string& key, bool fallback) {
    const toml::node* n = take(key);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(key, "must be true or false");
    return *n->value<bool>();
  }

  long long integer(const std::string& key, long long fallback, bool required = false) {
    const toml::node* n = take(key);
    if (!n) {
      if (required) fail(key, "missing (an integer is required)");
      return fallback;
    }
    if (!n->is_integer()) fail(key, "must be an integer");
    return *n->value<long long>();
  }

  std::string text(const std::string& key, const std::string& fallback, bool required = false) {
    const toml::node* n = take(key);
    if (!n) {
      if (required) fail(key, "missing (a string is required)");
      return fallback;
    }
    if (!n->is_string()) fail(key, "must be a string");
    return *n->value<std::string>();
  }

  template <int N>
  Eigen::Matrix<double, N, 1> vector(const std::string& key, const Eigen::Matrix<double, N, 1>& fallback,
                                     bool required = false) {
    const toml::node* n = take(key);
    if (!n) {
      if (required) fail(key, "missing (an array of " + std::to_string(N) + " numbers is required)");
      return fallback;
    }
    return read_vector<N>(*n, key);
  }

  template <int N>
  Eigen::Matrix<double, N, 1> read_vector(const toml::node& n, const std::string& key) const {
    const toml::array* array = n.as_array();
    if (!array || array->size() != N)
      fail(key, "must be an array of " + std::to_string(N) + " numbers");
    Eigen::Matrix<double, N, 1> v;
    for (int c = 0; c < N; ++c) {
      const auto value = (*array)[static_cast<std::size_t>(c)].value<double>();
      if (!value || (*array)[static_cast<std::size_t>(c)].is_boolean())
        fail(key, "must be an array of " + std::to_string(N) + " numbers");
      if (!std::isfinite(*value)) fail(key, "must hold finite numbers");
      v[c] = *value;
    }
    return v;
  }

  /// A value that may differ along warp and weft: a number (the same both ways) or [warp, weft].
  Eigen::Vector2d number_or_pair(const std::string& key) {
    const toml::node* n = take(key);
    if (!n) fail(key, "missing (a number, or an array [warp, weft], is required)");
    if (n->is_array()) return read_vector<2>(*n, key);
    const auto value = n->value<double>();
    if (!value || n->is_boolean()) fail(key, "must be a number or an array [warp, weft] of two numbers");
    if (!std::isfinite(*value)) fail(key, "must be finite");
    return Eigen::Vector2d::Constant(*value);
  }

  std::pair<long long, long long> integer_pair(const std::string& key, bool required) {
    const toml::node* n = take(key);
    if (!n) {
      if (required) fail(key, "missing (an array of two integers is required)");
      return {0, 0};
    }
    const toml::array* array = n->as_array();
    if (!array || array->size() != 2 || !(*array)[0].is_integer() || !(*array)[1].is_integer())
      fail(key, "must be an array of two integers");
    return {*(*array)[0].value<long long>(), *(*array)[1].value<long long>()};
  }

  TableReader table(const std::string& key, bool required) {
    const toml::node* n = take(key);
    if (!n) {
      if (required) fail(key, "missing (a table is required)");
      return TableReader(&empty_table(), dotted(key), file_, overridden_);
    }
    if (!n->is_table()) fail(key, "must be a table");
    return TableReader(n->as_table(), dotted(key), file_, overridden_);
  }

  std::vector<TableReader> tables(const std::string& key) {
    std::vector<TableReader> readers;
    const toml::node* n = take(key);
    if (!n) return readers;
    const toml::array* array = n->as_array();
    if (!array) fail(key, "must be an array of tables ([[" + dotted(key) + "]])");
    for (std::size_t i = 0; i < array->size(); ++i) {
      const toml::table* t = (*array)[i].as_table();
      if (!t) fail(key, "element " + std::to_string(i) + " must be a table");
      readers.emplace_back(t, dotted(key) + "." + std::to_string(i), file_, overridden_);
    }
    return readers;
  }

  /// Reports the first key nobody asked for.
  void reject_unknown(const std::vector<std::string>& known) const {
    for (auto&& [key, value] : *table_) {
      const std::string name(key.str());
      if (used_.count(name)) continue;
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError(locate(&value, dotted(shown(name))),
                       "unknown key" + (list.empty() ? std::string() : " (known here: " + list + ")"));
    }
  }

  SourceLocation where() const { return locate(table_, prefix_); }
  /// Where a key of this table was written (the table itself when the key is absent).
  SourceLocation locate_key(const std::string& key) const {
    return locate(node(key) ? node(key) : table_, dotted(key));
  }
  const std::string& file() const { return file_; }

 private:
  const toml::node* node(const std::string& key) const { return table_->get(key); }
  static const toml::table& empty_table() {
    static const toml::table empty;
    return empty;
  }

  const toml::table* table_;
  std::string prefix_;
  std::string file_;
  const OverriddenKeys& overridden_;
  std::set<std::string> used_;
};

}  // namespace fabform
