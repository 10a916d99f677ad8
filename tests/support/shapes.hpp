#pragma once
// Analytic shapes for tests whose answers are known in closed form.
#include <cmath>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform::test {

/// A closed UV sphere, outward-oriented (counter-clockwise seen from outside).
inline TriangleMesh uv_sphere(const Eigen::Vector3d& centre, double radius, int rings, int segments) {
  const double pi = 3.14159265358979323846;
  TriangleMesh mesh;
  mesh.vertices.push_back(centre + Eigen::Vector3d(0, 0, radius));
  for (int r = 1; r < rings; ++r) {
    const double theta = pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * pi * s / segments;
      mesh.vertices.push_back(centre + radius * Eigen::Vector3d(std::sin(theta) * std::cos(phi),
                                                                std::sin(theta) * std::sin(phi),
                                                                std::cos(theta)));
    }
  }
  mesh.vertices.push_back(centre - Eigen::Vector3d(0, 0, radius));
  const auto ring = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
  const int south = static_cast<int>(mesh.vertices.size()) - 1;
  for (int s = 0; s < segments; ++s) {
    mesh.triangles.push_back({0, ring(1, s), ring(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      mesh.triangles.push_back({ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
      mesh.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
    }
    mesh.triangles.push_back({ring(rings - 1, s), south, ring(rings - 1, s + 1)});
  }
  return mesh;
}

}  // namespace fabform::test
