#include "fabform/output/print_map_files.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fabform/error.hpp"
#include "fabform/number_text.hpp"

namespace fabform {
namespace {

// One vertex per node, its texture coordinate the node's; faces are triangles, "f a/a b/b c/c".
std::string textured_obj(const std::string& name, const char* what, const std::vector<Eigen::Vector3d>& vertices,
                         const std::vector<Eigen::Vector2d>& uv, const std::vector<std::array<int, 3>>& triangles) {
  NumberText out(12);
  out << "# fabform " << FABFORM_VERSION << ": " << what << "\nmtllib " << name << ".mtl\n";
  for (const auto& v : vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : uv) out << "vt " << t.x() << ' ' << t.y() << '\n';
  out << "usemtl " << name << '\n';
  for (const auto& t : triangles)
    out << "f " << t[0] + 1 << '/' << t[0] + 1 << ' ' << t[1] + 1 << '/' << t[1] + 1 << ' ' << t[2] + 1 << '/'
        << t[2] + 1 << '\n';
  return out.str();
}

InputError not_a_map(const std::string& path, int line, const std::string& why) {
  return InputError({path, line, ""}, why + " (not the flat-formed map a fabform run writes)");
}

}  // namespace

std::string formed_obj(const PrintMap& map, const std::vector<Eigen::Vector3d>& x) {
  return textured_obj("formed", "the formed fabric (metres); texture coordinates: its place in the flat blank", x,
                      map.blank_uv, map.triangles);
}

std::string blank_obj(const PrintMap& map, const std::vector<Eigen::Vector3d>& flat) {
  return textured_obj("blank", "the flat blank (metres); texture coordinates: its place in the developed view", flat,
                      map.developed_uv, map.triangles);
}

std::string map_mtl(const std::string& name) {
  return "# fabform " FABFORM_VERSION ": " + name + ".obj's texture (replace uv_grid.png, or name your image here)\n"
         "newmtl " + name + "\nKa 1 1 1\nKd 1 1 1\nmap_Kd uv_grid.png\n";
}

PrintMap read_blank_obj(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError({path, 0, ""}, "missing: the flat-formed map (a results folder of fabform run holds it)");
  std::ifstream in(path);
  std::vector<Eigen::Vector3d> flat;
  PrintMap map;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::istringstream words(text);
    std::string key;
    words >> key;
    if (key == "v") {
      Eigen::Vector3d p;
      if (!(words >> p.x() >> p.y() >> p.z()) || !p.allFinite()) throw not_a_map(path, line, "a vertex is not three numbers");
      flat.push_back(p);
    } else if (key == "vt") {
      Eigen::Vector2d t;
      if (!(words >> t.x() >> t.y()) || !t.allFinite()) throw not_a_map(path, line, "a texture coordinate is not two numbers");
      map.developed_uv.push_back(t);
    } else if (key == "f") {
      std::array<int, 3> t{};
      for (int& corner : t) {
        std::string ref;
        words >> ref;
        const std::size_t slash = ref.find('/');
        try {
          corner = std::stoi(ref.substr(0, slash)) - 1;
          if (slash == std::string::npos || std::stoi(ref.substr(slash + 1)) - 1 != corner) throw std::invalid_argument("");
        } catch (const std::exception&) {
          throw not_a_map(path, line, "a face is not three corners v/vt with v = vt");
        }
        if (corner < 0 || corner >= static_cast<int>(flat.size())) throw not_a_map(path, line, "a face names a vertex it does not have");
      }
      map.triangles.push_back(t);
    }
  }
  if (flat.empty() || map.triangles.empty() || map.developed_uv.size() != flat.size())
    throw not_a_map(path, 0, "no vertices and faces, or a texture coordinate missing for some vertex");
  const BlankFrame frame = blank_frame(flat);
  for (const auto& p : flat) map.blank_uv.push_back(frame.uv(p));
  return map;
}

}  // namespace fabform
