#pragma once
// Binary STL, read directly rather than through assimp: it is the format million-triangle CAD
// exports come in, a flat array of 50-byte float32 records, and assimp's generic path (a
// scene of per-face allocations, then JoinIdenticalVertices) takes several times as long as
// the bytes take to read. Internal to the mesh reader.
#include <string>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

/// Whether the file is a binary STL: at least 84 bytes, and exactly 84 + 50 × the count its
/// header declares (an ASCII STL never matches that by chance in practice).
bool is_binary_stl(const std::string& path);

/// Reads a binary STL, merging corners at bit-identical positions into one vertex (as assimp's
/// JoinIdenticalVertices does) because contact needs the mesh's topology. Throws InputError
/// naming the file for a coordinate that is not finite or a file that cannot be read.
TriangleMesh read_binary_stl(const std::string& path);

}  // namespace fabform
