#pragma once
// X3D's XML encoding (.x3d) translated to VRML97 text for the VRML reader (Coin reads no X3D).
// X3D 3 keeps VRML97's geometry nodes and fields, so the translation is a change of syntax for
// the nodes that make a body's surface: Transform, Group, Switch, Shape, IndexedFaceSet,
// Coordinate, Box, Sphere, Cylinder, Cone, Extrusion, ElevationGrid, and X3D's
// IndexedTriangleSet and TriangleSet (written as IndexedFaceSets), with DEF and USE. What does
// not shape a surface (appearance, viewpoints, sensors, routes, scripts, text, lines and points)
// is left out and counted. Internal: read_mesh sends .x3d files here.
#include <map>
#include <string>

namespace fabform {

struct X3dTranslation {
  std::string vrml;                     // VRML97 text, header first
  std::map<std::string, int> left_out;  // X3D element name → how many were left out
};

/// Throws InputError naming the file (and the line) when it is not well-formed XML, not X3D,
/// or a geometry field holds something other than numbers (or, for booleans, true or false).
X3dTranslation translate_x3d(const std::string& path);

/// The same for the file's text (`path` names it in errors).
X3dTranslation translate_x3d_text(const std::string& text, const std::string& path);

}  // namespace fabform
