#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

BoundingBox bounding_box(const std::vector<Eigen::Vector3d>& points) {
  BoundingBox box;
  if (points.empty()) return box;
  box.min = box.max = points.front();
  for (const auto& p : points) {
    box.min = box.min.cwiseMin(p);
    box.max = box.max.cwiseMax(p);
  }
  return box;
}

}  // namespace fabform
