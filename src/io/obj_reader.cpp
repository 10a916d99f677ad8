#include "io/obj_reader.hpp"

#include <cstdlib>
#include <utility>
#include <vector>

#include "fabform/geometry/polygon_triangulation.hpp"
#include "io/text_lines.hpp"
#include "io/vertex_welder.hpp"

namespace fabform {
namespace {

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
      const Eigen::Vector3d& p = positions_[position_of(line.words[c])];
      index.push_back(welder_.index_of(p));
      points.push_back(p);
    }
    for (const auto& t : triangulate_polygon(points))
      out_.mesh.triangles.push_back({index[static_cast<std::size_t>(t[0])], index[static_cast<std::size_t>(t[1])],
                                     index[static_cast<std::size_t>(t[2])]});
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

  std::vector<Eigen::Vector3d> positions_;
  ObjMesh out_;
  VertexWelder welder_{&out_.mesh.vertices};  // only corners of faces become vertices
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
