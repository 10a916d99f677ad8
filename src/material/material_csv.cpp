#include "fabform/material/material_csv.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <regex>
#include <stdexcept>

#include "fabform/error.hpp"

namespace fabform {
namespace {

constexpr std::size_t kMaxLineLength = 4096;
constexpr std::size_t kMaxPoints = 100000;

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

struct Cells {
  std::string first, second;
};

std::optional<Cells> split_pair(const std::string& line) {
  const auto comma = line.find(',');
  if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos)
    return std::nullopt;
  return Cells{trim(line.substr(0, comma)), trim(line.substr(comma + 1))};
}

// The format's number grammar (materials/README.md): [+-]? (D+ ('.' D*)? | '.' D+) ([eE][+-]?D+)?
// strtod alone would also take hex floats, "inf" and "nan".
bool is_decimal_number(const std::string& cell) {
  static const std::regex grammar(R"([+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?)");
  return std::regex_match(cell, grammar);
}

std::optional<double> parse_number(const std::string& cell) {
  if (!is_decimal_number(cell)) return std::nullopt;
  const double value = std::strtod(cell.c_str(), nullptr);
  if (!std::isfinite(value)) return std::nullopt;  // overflow; underflow to 0 is fine
  return value;
}

class TableParser {
 public:
  explicit TableParser(std::string source) : source_(std::move(source)) {}

  MaterialFile parse(std::istream& in) {
    std::string raw;
    while (std::getline(in, raw)) {
      ++line_;
      if (raw.size() > kMaxLineLength) fail("line longer than 4096 characters");
      const std::string line = trim(raw);
      if (line.empty() || line[0] == '#') continue;
      take(line);
    }
    return finish();
  }

 private:
  [[noreturn]] void fail(const std::string& message, int line = -1) const {
    throw InputError({source_, line < 0 ? line_ : line, ""}, message);
  }

  void take(const std::string& line) {
    const auto cells = split_pair(line);
    if (!cells) fail("expected two comma-separated cells, got '" + line + "'");
    if (!header_seen_) return take_before_header(*cells);
    take_point(*cells);
  }

  // A `key,value` directive whose value must be positive: stored once, with its line.
  void take_positive(const Cells& cells, const char* unit, std::optional<double>* value, int* line) {
    if (*value) fail(cells.first + " is given twice");
    *value = parse_number(cells.second);
    if (!*value || **value <= 0.0) fail(cells.first + " must be a positive number of " + unit);
    *line = line_;
  }

  void take_before_header(const Cells& cells) {
    if (cells.first == "areal_density_kg_m2")
      return take_positive(cells, "kg/m²", &areal_density_kg_m2_, &areal_density_line_);
    if (cells.first == "thickness_m") return take_positive(cells, "metres", &thickness_m_, &thickness_line_);
    if (cells.first != "strain")
      fail("expected the header 'strain,tension_N_per_m' or 'strain,stress_Pa', or a "
           "'thickness_m,VALUE' or 'areal_density_kg_m2,VALUE' line before it; got '" + cells.first + "," + cells.second + "'");
    if (cells.second == "stress_Pa") {
      is_stress_ = true;
    } else if (cells.second != "tension_N_per_m") {
      fail("unknown unit column '" + cells.second + "' (expected tension_N_per_m or stress_Pa)");
    }
    header_seen_ = true;
    header_line_ = line_;
  }

  void take_point(const Cells& cells) {
    const auto strain = parse_number(cells.first);
    const auto value = parse_number(cells.second);
    if (!strain) fail("strain '" + cells.first + "' is not a finite number");
    if (!value) fail("value '" + cells.second + "' is not a finite number");
    if (!points_.empty() && !(*strain > points_.back().strain))
      fail("strain must increase strictly: " + cells.first + " follows " +
           std::to_string(points_.back().strain));
    if (points_.size() >= kMaxPoints) fail("more than 100000 points");
    if (!points_.empty() && *value < points_.back().tension_N_per_m && falling_line_ == 0) falling_line_ = line_;
    points_.push_back({*strain, *value});
    if (points_.size() == 1) first_point_line_ = line_;
  }

  MaterialFile finish() {
    if (!header_seen_) fail("no header line 'strain,tension_N_per_m' or 'strain,stress_Pa'", 0);
    if (is_stress_ && !thickness_m_)
      fail("a stress_Pa table needs a 'thickness_m,VALUE' line before its header", header_line_);
    if (!is_stress_ && thickness_m_)
      fail("thickness_m is only meaningful for a stress_Pa table", thickness_line_);
    if (points_.size() < 2) fail("a table needs at least two points", 0);
    if (is_stress_)
      for (auto& point : points_) point.tension_N_per_m *= *thickness_m_;
    try {
      return {TensionTable(points_, source_), areal_density_kg_m2_, areal_density_line_, falling_line_};
    } catch (const std::invalid_argument& error) {
      fail(error.what(), first_point_line_);
    }
  }

  std::string source_;
  int line_ = 0;
  int header_line_ = 0;
  int thickness_line_ = 0;
  int areal_density_line_ = 0;
  int first_point_line_ = 0;
  int falling_line_ = 0;
  bool header_seen_ = false;
  bool is_stress_ = false;
  std::optional<double> thickness_m_;
  std::optional<double> areal_density_kg_m2_;
  std::vector<TablePoint> points_;
};

}  // namespace

MaterialFile parse_material_file(std::istream& in, const std::string& source_name) {
  return TableParser(source_name).parse(in);
}

MaterialFile read_material_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, ""}, "cannot open the material table");
  return parse_material_file(in, path);
}

TensionTable parse_material_table(std::istream& in, const std::string& source_name) {
  return parse_material_file(in, source_name).table;
}

TensionTable read_material_table(const std::string& path) { return read_material_file(path).table; }

}  // namespace fabform
