#pragma once
// The flat ↔ formed map in a results folder, as OBJ files any 3D viewer opens with their
// texture (print_map.hpp defines the frame and the developed view):
//   formed.obj + formed.mtl  the formed fabric, each vertex's texture coordinate its place in
//                            the flat blank: textured by the image printed on the blank, it
//                            shows what the formed part looks like;
//   blank.obj + blank.mtl    the inverse: the flat blank (metres, where the scene lays it), each
//                            vertex's texture coordinate its place in the developed view:
//                            textured by a design, it shows what to print. `fabform predistort`
//                            reads this file.
//   uv_grid.png              the texture both name until a design or print replaces it: a
//                            checkerboard (squares of the blank's grid on formed.obj).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/analysis/print_map.hpp"

namespace fabform {

std::string formed_obj(const PrintMap& map, const std::vector<Eigen::Vector3d>& x);
std::string blank_obj(const PrintMap& map, const std::vector<Eigen::Vector3d>& flat);
/// The material file of formed.obj or blank.obj ("formed" or "blank"), naming uv_grid.png.
std::string map_mtl(const std::string& name);

/// The map blank.obj holds; throws InputError naming the file when it is missing or is not a
/// map fabform wrote.
PrintMap read_blank_obj(const std::string& path);

}  // namespace fabform
