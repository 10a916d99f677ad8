#pragma once
// The checks every table of a scene makes of its values (sizes, angles, names, counts, paths
// relative to the scene), shared by the scene's readers. Internal to the scene parser.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <Eigen/Core>

#include "scene/toml_table_reader.hpp"

namespace fabform::scene_values {

inline std::string resolve(const std::string& scene_path, const std::string& path) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(scene_path).parent_path() / path).lexically_normal().string();
}

inline int checked_int(TableReader& r, const std::string& key, long long value, long long lo, long long hi) {
  if (value < lo || value > hi)
    r.fail(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return static_cast<int>(value);
}

// The model builder refuses a start or a placed mesh reaching beyond 1e6 m (a unit mistake;
// Embree works in single precision), naming the body or the initial shape; a huge fabric size
// would be blamed on the initial shape, so the size is bounded here, where its key is known.
constexpr double kMaxLength_m = 1e6;
// An angle is written within one turn; far beyond it (1e300) the remainder is rounding noise,
// and nothing downstream notices.
constexpr double kMaxAngle_deg = 360.0;

// %g, with the exponent as a scene writes it: 1e6, not 1e+06.
inline std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  std::string out = text;
  for (const char* padding : {"e+0", "e+", "e-0"}) {
    const std::size_t at = out.find(padding);
    if (at != std::string::npos) out.replace(at, std::string(padding).size(), padding[1] == '-' ? "e-" : "e");
  }
  return out;
}

inline bool has_control_character(const std::string& value) { return shown(value) != value; }

inline void check_magnitude(TableReader& r, const std::string& key, double magnitude, double limit,
                            const char* unit) {
  if (magnitude > limit)
    r.fail(key, "must be between -" + number_text(limit) + " and " + number_text(limit) + " " + unit);
}

inline double angle(TableReader& r, const std::string& key, double fallback, bool required = false) {
  const double value = r.number(key, fallback, required);
  check_magnitude(r, key, std::abs(value), kMaxAngle_deg, "degrees");
  return value;
}

template <int N>
inline Eigen::Matrix<double, N, 1> angles(TableReader& r, const std::string& key) {
  const Eigen::Matrix<double, N, 1> value = r.vector<N>(key, Eigen::Matrix<double, N, 1>::Zero());
  check_magnitude(r, key, value.cwiseAbs().maxCoeff(), kMaxAngle_deg, "degrees");
  return value;
}

// A name or path that is empty or holds a control character is never what was meant: "" names
// no file (or, for output.dir, the current folder), and names and paths are echoed into
// one-line messages and file headers. Only a value written is checked; a key left out takes
// its default.
inline std::string plain_text(TableReader& r, const std::string& key, const std::string& fallback,
                              bool required = false) {
  std::string value = r.text(key, fallback, required);
  if (r.has(key) && value.empty()) r.fail(key, "must not be empty");
  if (has_control_character(value)) r.fail(key, "must not hold control characters (got '" + shown(value) + "')");
  return value;
}

// The scene's name is its default results folder, results/NAME: one folder name, so that a run
// cannot write beside or above results/.
inline std::string read_scene_name(TableReader& r, const std::string& fallback) {
  const std::string name = plain_text(r, "name", fallback);
  if (name == "." || name == ".." || name.find_first_of("/\\") != std::string::npos)
    r.fail("name", "must be a plain folder name (no / and not . or ..); output.dir takes a path");
  return name;
}

inline void check_size(TableReader& r, const std::string& key, double size) {
  if (!(size > 0.0)) r.fail(key, "must be positive");
  if (size > kMaxLength_m) r.fail(key, "must be at most " + number_text(kMaxLength_m) + " m");
}

}  // namespace fabform::scene_values
