#pragma once
// Wavefront OBJ, read by fabform rather than assimp: assimp 5.2.5 holds coordinates as float,
// so an OBJ written to 17 digits (fabform check --repair) came back moved by up to half a float
// step, with vertices nearer than that merged into one (non-manifold edges where there were
// none); and a face of more than three corners is cut by triangulate_polygon (ear clipping in
// its plane). Internal to the mesh reader, after check_mesh_file has checked the text.
#include <string>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

struct ObjMesh {
  TriangleMesh mesh;                // corners at the same position are one vertex; unused vertices are left out
  unsigned points_and_lines = 0;    // p points, l segments and faces of fewer than three corners: no surface
};

/// The triangles of OBJ text whose records check_mesh_file has checked (indices in range,
/// coordinates finite). Only v and f records shape the body; l and p are counted, the rest
/// (vt, vn, g, o, s, usemtl, mtllib, ...) say nothing about it.
ObjMesh read_obj_text(const std::string& text);

}  // namespace fabform
