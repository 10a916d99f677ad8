#pragma once
// One place turns what a command throws into its message and exit status, so that every command
// tells bad input (2) from what the system refused (5) and from a bug of fabform's own (70).
#include <functional>

namespace fabform::cli {

/// Runs `command` and returns its status; an exception is reported on one line of stderr and
/// becomes the status of its kind.
int guarded(const std::function<int()>& command);

}  // namespace fabform::cli
