#pragma once
// Reads a rigid body's triangles from a CAD export (OBJ, STL ASCII or binary, PLY, OFF and
// the other formats assimp reads; VRML97 .wrl/.wrz through Coin3D), in the file's own units.
#include <string>
#include <vector>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

/// Throws InputError naming the file (and the line, in text) when it is missing, a folder,
/// cannot be read or holds no triangle. When warnings is not null, what was skipped or is
/// doubtful (points and lines; VRML: shapes without geometry, text, two-sided faces; binary
/// STL: bytes after its triangles) is appended to it, one line each.
TriangleMesh read_mesh(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace fabform
