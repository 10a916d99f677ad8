#pragma once
// Where tests find the repository's files and the fabform binary.
#include <string>

namespace fabform::test {

inline std::string source_path(const std::string& relative) {
  return std::string(FABFORM_SOURCE_DIR) + "/" + relative;
}

inline std::string fabform_binary() { return FABFORM_BINARY; }

}  // namespace fabform::test
