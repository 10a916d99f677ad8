#pragma once
// Reads a rigid body's triangles from a VRML97 file (.wrl, plain or gzip-compressed) through
// Coin3D, in the file's own units, with every Transform applied. Internal: callers use
// read_mesh (fabform/io/mesh_reader.hpp), which sends .wrl files here.
#include <string>
#include <vector>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

/// What is read: the Shapes a VRML97 browser would draw (Transform/Group children, the chosen
/// child of a Switch, one copy per USE) whose geometry is an IndexedFaceSet (concave polygons
/// triangulated), Box, Sphere, Cylinder, Cone (tessellated by Coin), Extrusion or ElevationGrid.
/// Triangles of geometry with `ccw FALSE`, or under a mirroring Transform, are reversed so that
/// their normals (right-hand rule) point to the front face the file declares. Identical
/// positions are joined into one vertex.
///
/// Appends one line per kind of skipped or doubtful content to *warnings (when not null):
/// Shapes without geometry, Text, lines and points, geometry that gave no triangles, geometry
/// marked `solid FALSE` (two-sided: its faces are not promised to point outward), and Coin's
/// own warnings.
///
/// Throws InputError naming the file: a missing or empty file, a first line other than
/// `#VRML V2.0 utf8`, anything Coin cannot parse (with the line Coin reports), an index out of
/// range, or no triangles at all. Coin prints nothing: its messages are captured.
/// Thread-safe (reads are serialised: Coin's scene database is global).
TriangleMesh read_vrml(const std::string& path, std::vector<std::string>* warnings);

/// The same for VRML97 text standing for the file `path` (a translation of it, as X3D's):
/// errors name `path`; Inlines resolve against its folder.
TriangleMesh read_vrml_text(const std::string& text, const std::string& path, std::vector<std::string>* warnings);

}  // namespace fabform
