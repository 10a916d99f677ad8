#pragma once
// A study's own files (study.json, study.csv) change all at once: written beside their name,
// then renamed over it, so a reader or a killed study never finds half a file.
#include <string>

namespace fabform {

/// Writes `text` to `path` through a temporary file renamed into place. Throws
/// std::runtime_error naming the file when it cannot.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace fabform
