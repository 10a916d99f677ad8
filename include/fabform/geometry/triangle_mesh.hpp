#pragma once
// A rigid body's surface as CAD exports it: points and triangles (seed 003, §4), in metres
// once placed.
#include <array>
#include <vector>

#include <Eigen/Core>

namespace fabform {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

struct BoundingBox {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(0.0);
  Eigen::Vector3d max = Eigen::Vector3d::Constant(0.0);
  double diagonal() const { return (max - min).norm(); }
};

BoundingBox bounding_box(const std::vector<Eigen::Vector3d>& points);

}  // namespace fabform
