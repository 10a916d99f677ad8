#include "fabform/error.hpp"

namespace fabform {

std::string format_located(const SourceLocation& where, const std::string& message) {
  std::string text;
  if (!where.file.empty()) {
    text += where.file;
    if (where.line > 0) text += ":" + std::to_string(where.line);
    text += ": ";
  }
  if (!where.key.empty()) text += where.key + ": ";
  return text + message;
}

InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(format_located(where, message)),
      where_(std::move(where)),
      message_(message) {}

}  // namespace fabform
