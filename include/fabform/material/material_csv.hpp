#pragma once
// Reads a fabform material table (CSV, version 2; the format is specified in
// materials/README.md). Parsing stays here, at the edge: the rest of fabform sees a
// TensionTable in N/m.
#include <istream>
#include <optional>
#include <string>

#include "fabform/material/tension_table.hpp"

namespace fabform {

/// What a material file says: its tension table and, when it has the directive, the fabric's
/// mass per area (what gravity acts on).
struct MaterialFile {
  TensionTable table;
  std::optional<double> areal_density_kg_m2;
  int areal_density_line = 0;  // where the directive is, for errors about it
  int falling_line = 0;        // the first point whose value is below the one before (0: never falls)
};

/// Reads a material file; throws InputError naming the file and line on any problem.
MaterialFile read_material_file(const std::string& path);

/// Parses a material file from a stream; `source_name` is used in error messages.
MaterialFile parse_material_file(std::istream& in, const std::string& source_name);

/// Reads a table file (its table alone); throws InputError naming the file and line on any problem.
TensionTable read_material_table(const std::string& path);

/// Parses a table from a stream; `source_name` is used in error messages.
TensionTable parse_material_table(std::istream& in, const std::string& source_name);

}  // namespace fabform
