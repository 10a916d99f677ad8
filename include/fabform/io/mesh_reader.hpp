#pragma once
// Reads a rigid body's triangles from a CAD export (OBJ, STL ASCII or binary, PLY, OFF and
// the other formats assimp reads), in the file's own units.
#include <string>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

/// Throws InputError naming the file when it cannot be read or holds no triangle.
TriangleMesh read_mesh(const std::string& path);

}  // namespace fabform
