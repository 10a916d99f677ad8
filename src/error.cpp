#include "fabform/error.hpp"

#include <cstring>

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

SystemError::SystemError(const std::string& subject, const std::string& doing, const std::string& reason)
    : std::runtime_error(subject + ": cannot " + doing + " (" + reason + ")") {}

std::string system_reason(int errnum) { return std::strerror(errnum); }

}  // namespace fabform
