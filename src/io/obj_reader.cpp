#include "io/obj_reader.hpp"

#include <array>
#include <cstdlib>
#include <functional>
#include <unordered_map>
#include <vector>

#include "fabform/geometry/polygon_triangulation.hpp"
#include "io/text_lines.hpp"

namespace fabform {
namespace {

struct PositionHash {
  std::size_t operator()(const std::array<double, 3>& p) const {
    std::size_t h = 0;
    for (const double x : p) h = h * 1000003u ^ std::hash<double>{}(x);
    return h;
  }
};

class ObjBuilder {
 public:
  void vertex(const Line& line) {
    positions_.emplace_back(std::strtod(line.words[1].c_str(), nullptr), std::strtod(line.words[2].c_str(), nullptr),
                            std::strtod(line.words[3].c_str(), nullptr));
  }

  void face(const Line& line) {
    const std::size_t corners = line.words.size() - 1;
    if (corners < 3) {
      ++out_.points_and_lines;
      return;
    }
    std::vector<int> index;
    std::vector<Eigen::Vector3d> points;
    for (std::size_t c = 1; c <= corners; ++c) {
      const std::size_t position = position_of(line.words[c]);
      index.push_back(vertex_at(position));
      points.push_back(positions_[position]);
    }
    for (const auto& t : triangulate_polygon(points)) out_.mesh.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  }

  // As assimp counts them: a line of n corners is n - 1 segments, a point record of n corners n points.
  void lines_or_points(const Line& line) {
    const auto corners = static_cast<unsigned>(line.words.size() - 1);
    out_.points_and_lines += line.words[0] == "l" && corners > 1 ? corners - 1 : corners;
  }

  ObjMesh finish() { return std::move(out_); }

 private:
  // "v", "v/t", "v//n" or "v/t/n", from 1, or back from the last vertex read when negative.
  std::size_t position_of(const std::string& corner) const {
    const long long i = std::strtoll(corner.c_str(), nullptr, 10);
    return static_cast<std::size_t>(i > 0 ? i - 1 : static_cast<long long>(positions_.size()) + i);
  }

  // One vertex per position, as assimp's JoinIdenticalVertices makes it: contact needs the
  // topology. + 0.0 turns -0 into +0, which compares equal but would hash apart.
  int vertex_at(std::size_t position) {
    const Eigen::Vector3d& p = positions_[position];
    const std::array<double, 3> key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
    const auto [it, inserted] = vertex_of_.emplace(key, static_cast<int>(out_.mesh.vertices.size()));
    if (inserted) out_.mesh.vertices.push_back(p);
    return it->second;
  }

  std::vector<Eigen::Vector3d> positions_;
  std::unordered_map<std::array<double, 3>, int, PositionHash> vertex_of_;
  ObjMesh out_;
};

}  // namespace

ObjMesh read_obj_text(const std::string& text) {
  ObjBuilder builder;
  Line line;
  for (TextLines lines(text, 0, 1, true); lines.next(&line);) {
    const std::string& keyword = line.words[0];
    if (keyword == "v") builder.vertex(line);
    else if (keyword == "f") builder.face(line);
    else if (keyword == "l" || keyword == "p") builder.lines_or_points(line);
  }
  return builder.finish();
}

}  // namespace fabform
