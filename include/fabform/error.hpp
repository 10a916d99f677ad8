#pragma once
// Errors fabform reports to its user: bad input (exit status 2) names the file, the line
// when the format has lines, the key when there is one, and what is wrong.
#include <stdexcept>
#include <string>

namespace fabform {

/// Where a bad value came from: a file, a 1-based line (0 = none), a dotted key ("" = none).
struct SourceLocation {
  std::string file;
  int line = 0;
  std::string key;
};

/// Bad input from a file or the command line. what() is the one-line message shown to users:
/// "FILE:LINE: KEY: MESSAGE" with the absent parts left out.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message);
  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

/// Formats a location and message the way InputError::what() does.
std::string format_located(const SourceLocation& where, const std::string& message);

}  // namespace fabform
