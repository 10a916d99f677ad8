#pragma once
// Reads a fabform material table (CSV, version 1; the format is specified in
// materials/README.md). Parsing stays here, at the edge: the rest of fabform sees a
// TensionTable in N/m.
#include <istream>
#include <string>

#include "fabform/material/tension_table.hpp"

namespace fabform {

/// Reads a table file; throws InputError naming the file and line on any problem.
TensionTable read_material_table(const std::string& path);

/// Parses a table from a stream; `source_name` is used in error messages.
TensionTable parse_material_table(std::istream& in, const std::string& source_name);

}  // namespace fabform
