#pragma once
// A mesh file's format is read from its extension, whatever its case.
#include <cctype>
#include <filesystem>
#include <string>

namespace fabform {

/// The file name's extension, lower case, with its dot ("" when none).
inline std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace fabform
