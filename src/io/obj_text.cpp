#include "fabform/io/obj_text.hpp"

#include "fabform/number_text.hpp"

namespace fabform {

std::string obj_text(const TriangleMesh& mesh, const std::string& comment) {
  NumberText obj(17);
  if (!comment.empty()) obj << "# " << comment << '\n';
  for (const auto& v : mesh.vertices) obj << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles) obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  return obj.str();
}

}  // namespace fabform
