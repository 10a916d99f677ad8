#pragma once
// Mesh formats that declare their element counts up front (binary STL, PLY, OFF) are checked
// against the file's size before any reader allocates for them: a 100-byte file declaring a
// billion faces is refused, not trusted. Internal to the mesh reader.
#include <string>

namespace fabform {

/// Throws InputError naming the file when a declared count cannot fit in the file.
void check_declared_counts(const std::string& path);

}  // namespace fabform
