#pragma once
// A triangle mesh as Wavefront OBJ text: what `fabform check --repair` writes, and a mesh any
// CAD tool or fabform itself reads back exactly (17 significant digits round-trip a double).
#include <string>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

/// OBJ text: `comment` on a first "# " line (none when empty), then v and f records.
std::string obj_text(const TriangleMesh& mesh, const std::string& comment = "");

}  // namespace fabform
