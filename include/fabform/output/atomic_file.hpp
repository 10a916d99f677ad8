#pragma once
// Files fabform writes change all at once: written beside their name, then renamed over it, so a
// reader or a killed process never finds half a file. A failed write says the system's reason
// (a full disk, a missing permission) and leaves what was there before.
#include <string>

namespace fabform {

/// Writes `text` to `path` (created or truncated). Throws SystemError naming the file and the
/// system's reason when it cannot, with the partial file removed.
void write_file(const std::string& path, const std::string& text);

/// Writes `text` to `path` through a temporary file renamed into place. Throws SystemError
/// naming the file and the system's reason when it cannot; `path` then holds what it held.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace fabform
