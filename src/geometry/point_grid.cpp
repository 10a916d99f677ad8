#include "fabform/geometry/point_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fabform {
namespace {

// Cube coordinates are clamped to this, so a point far off (or not finite) cannot overflow them;
// such points share the outermost cubes, which stays correct, only slower.
constexpr double kMaxCube = 1e15;

long long cube_coordinate(double value) {
  if (!(value == value)) return 0;  // NaN
  return static_cast<long long>(std::clamp(std::floor(value), -kMaxCube, kMaxCube));
}

}  // namespace

PointGrid::PointGrid(const std::vector<Eigen::Vector3d>& points, double cell)
    : cell_(std::isfinite(cell) && cell > 0.0 ? cell : 1.0) {
  binned_.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) binned_.emplace_back(key_of(points[i]), static_cast<int>(i));
  std::sort(binned_.begin(), binned_.end());
}

PointGrid::Key PointGrid::key_of(const Eigen::Vector3d& p) const {
  return {cube_coordinate(p.x() / cell_), cube_coordinate(p.y() / cell_), cube_coordinate(p.z() / cell_)};
}

std::vector<int> PointGrid::near(const Eigen::Vector3d& q) const {
  const Key centre = key_of(q);
  std::vector<int> found;
  for (long long dx = -1; dx <= 1; ++dx)
    for (long long dy = -1; dy <= 1; ++dy)
      for (long long dz = -1; dz <= 1; ++dz) {
        const Key cube{centre[0] + dx, centre[1] + dy, centre[2] + dz};
        auto first = std::lower_bound(binned_.begin(), binned_.end(), std::make_pair(cube, std::numeric_limits<int>::min()));
        for (; first != binned_.end() && first->first == cube; ++first) found.push_back(first->second);
      }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace fabform
