#pragma once
// Binary STL, read directly rather than through assimp: it is the format million-triangle CAD
// exports come in, a flat array of 50-byte float32 records, and assimp's generic path (a
// scene of per-face allocations, then JoinIdenticalVertices) takes several times as long as
// the bytes take to read. Internal to the mesh reader.
#include <cstdint>
#include <optional>
#include <string>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

/// The bytes after a binary STL's declared triangles (0 when it ends with them), or nothing
/// when the file is not a binary STL. It is one when it holds at least 84 + 50 × the count its
/// header declares: exactly that many bytes (an ASCII STL never matches that by chance in
/// practice), or more, unless it reads as ASCII (it starts with "solid" and its first record
/// holds no NUL byte). Common readers ignore such trailing bytes; so does fabform, and says so.
std::optional<std::uintmax_t> binary_stl_trailing_bytes(const std::string& path);

/// Whether binary_stl_trailing_bytes finds a binary STL.
bool is_binary_stl(const std::string& path);

/// Reads a binary STL, merging corners at bit-identical positions into one vertex (as assimp's
/// JoinIdenticalVertices does) because contact needs the mesh's topology. Throws InputError
/// naming the file for a coordinate that is not finite or a file that cannot be read.
TriangleMesh read_binary_stl(const std::string& path);

}  // namespace fabform
