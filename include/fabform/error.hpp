#pragma once
// Errors fabform reports to its user: bad input (exit status 2) names the file, the line
// when the format has lines, the key when there is one, and what is wrong; what the system
// refused (exit status 5) names what was asked and the system's reason.
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

/// The system refused what fabform asked of it: a write to a full disk or a folder without
/// permission, a process that could not start, memory. what() is "SUBJECT: cannot DOING (REASON)".
class SystemError : public std::runtime_error {
 public:
  SystemError(const std::string& subject, const std::string& doing, const std::string& reason);
};

/// The system's reason for errno value `errnum` ("No space left on device").
std::string system_reason(int errnum);

/// Formats a location and message the way InputError::what() does.
std::string format_located(const SourceLocation& where, const std::string& message);

}  // namespace fabform
