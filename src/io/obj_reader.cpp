#include "io/obj_reader.hpp"

#include <cstdlib>
#include <utility>
#include <vector>

#include "fabform/geometry/polygon_triangulation.hpp"
#include "io/text_lines.hpp"
#include "io/vertex_welder.hpp"

namespace fabform {
namespace {

Eigen::Vector3d position(const Line& line) {
  return {std::strtod(line.words[1].c_str(), nullptr), std::strtod(line.words[2].c_str(), nullptr),
          std::strtod(line.words[3].c_str(), nullptr)};
}

// Every v record of the text: a face may name a vertex listed after it (check_mesh_file checks
// positive indices against all the file's vertices, as assimp resolves them).
std::vector<Eigen::Vector3d> positions_of(const std::string& text) {
  std::vector<Eigen::Vector3d> positions;
  Line line;
  for (TextLines lines(text, 0, 1, true); lines.next(&line);)
    if (line.words[0] == "v") positions.push_back(position(line));
  return positions;
}

class ObjBuilder {
 public:
  explicit ObjBuilder(std::vector<Eigen::Vector3d> positions) : positions_(std::move(positions)) {}
  ObjBuilder(const ObjBuilder&) = delete;  // welder_ points into this object's own mesh
  ObjBuilder& operator=(const ObjBuilder&) = delete;

  void vertex() { ++read_; }

  void face(const Line& line) {
    const std::size_t corners = line.words.size() - 1;
    if (corners < 3) {
      ++out_.points_and_lines;
      return;
    }
    std::vector<int> index;
    std::vector<Eigen::Vector3d> points;
    for (std::size_t c = 1; c <= corners; ++c) {
      // at(): check_mesh_file checked the indices, but of its own read of the file, which may
      // have changed since; a wrong index must not read past the positions.
      const Eigen::Vector3d& p = positions_.at(position_of(line.words[c]));
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
    return static_cast<std::size_t>(i > 0 ? i - 1 : static_cast<long long>(read_) + i);
  }

  const std::vector<Eigen::Vector3d> positions_;
  std::size_t read_ = 0;  // v records before the current line
  ObjMesh out_;
  VertexWelder welder_{&out_.mesh.vertices};  // only corners of faces become vertices
};

}  // namespace

ObjMesh read_obj_text(const std::string& text) {
  ObjBuilder builder(positions_of(text));
  Line line;
  for (TextLines lines(text, 0, 1, true); lines.next(&line);) {
    const std::string& keyword = line.words[0];
    if (keyword == "v") builder.vertex();
    else if (keyword == "f") builder.face(line);
    else if (keyword == "l" || keyword == "p") builder.lines_or_points(line);
  }
  return builder.finish();
}

}  // namespace fabform
