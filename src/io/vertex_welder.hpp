#pragma once
// One vertex per position, as assimp's JoinIdenticalVertices makes it: a file lists a corner
// once per face, and contact needs the mesh's topology. Internal to the mesh readers (OBJ,
// VRML); the binary STL reader has a float-keyed table of its own, for speed.
#include <array>
#include <cstddef>
#include <functional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace fabform {

class VertexWelder {
 public:
  explicit VertexWelder(std::vector<Eigen::Vector3d>* vertices) : vertices_(vertices) {}

  /// The index of the vertex at p, appended to the vertices when no vertex is there yet.
  int index_of(const Eigen::Vector3d& p) {
    // + 0.0 turns -0 into +0, which compares equal but would hash apart.
    const std::array<double, 3> key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
    const auto [it, inserted] = index_.emplace(key, static_cast<int>(vertices_->size()));
    if (inserted) vertices_->push_back(p);
    return it->second;
  }

 private:
  struct Hash {
    std::size_t operator()(const std::array<double, 3>& p) const {
      std::size_t h = 0;
      for (const double x : p) h = h * 1000003u ^ std::hash<double>{}(x);
      return h;
    }
  };

  std::vector<Eigen::Vector3d>* vertices_;
  std::unordered_map<std::array<double, 3>, int, Hash> index_;
};

}  // namespace fabform
