// What the commands share of reading the command line that CLI11 parsed.
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"

namespace fabform::cli {

InputError usage_error(const std::string& option, const std::string& why) {
  return InputError({"command line", 0, option}, why);
}

void refuse_leftovers(const CLI::App& command, const std::string& why) {
  for (const std::string& left : command.remaining())
    throw usage_error(left, !left.empty() && left[0] == '-' ? "unknown option" : why);
}

const std::vector<std::string>& values_of(const CLI::App& command, const std::string& option) {
  return command.get_option(option)->results();
}

const std::string* given(const CLI::App& command, const std::string& option) {
  const std::vector<std::string>& values = values_of(command, option);
  return values.empty() ? nullptr : &values.back();
}

}  // namespace fabform::cli
