#pragma once
// Analytic shapes for tests whose answers are known in closed form.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform::test {

/// A closed cylinder of radius r about the y axis, from y0 to y1, with end caps, outward.
inline TriangleMesh cylinder_along_y(double r, double y0, double y1, int segments) {
  const double pi = std::acos(-1.0);
  TriangleMesh mesh;
  for (const double y : {y0, y1})
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * pi * s / segments;
      mesh.vertices.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
    }
  mesh.vertices.emplace_back(0.0, y0, 0.0);
  mesh.vertices.emplace_back(0.0, y1, 0.0);
  const int front = 2 * segments, back = front + 1;
  for (int s = 0; s < segments; ++s) {
    const int a = s, b = (s + 1) % segments, c = a + segments, d = b + segments;
    mesh.triangles.push_back({a, c, d});
    mesh.triangles.push_back({a, d, b});
    mesh.triangles.push_back({front, a, b});
    mesh.triangles.push_back({back, d, c});
  }
  return mesh;
}

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

/// uv_sphere with its poles on the y axis, so that a fabric laid on top meets regular facets
/// rather than the slivers round a pole.
inline TriangleMesh sideways_sphere(const Eigen::Vector3d& centre, double radius, int rings,
                                    int segments) {
  TriangleMesh mesh = uv_sphere(Eigen::Vector3d::Zero(), radius, rings, segments);
  for (Eigen::Vector3d& v : mesh.vertices) v = centre + Eigen::Vector3d(v.x(), -v.z(), v.y());
  return mesh;
}

/// The cube [0,size]³ moved by offset (vertex k at x = k&1, y = (k>>1)&1, z = (k>>2)&1),
/// triangles counter-clockwise seen from outside.
inline TriangleMesh cube(const Eigen::Vector3d& offset = Eigen::Vector3d::Zero(), double size = 1.0) {
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k)
    mesh.vertices.push_back(offset + size * Eigen::Vector3d(k & 1, (k >> 1) & 1, (k >> 2) & 1));
  mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return mesh;
}

/// Reverses a triangle's winding.
inline void flip(std::array<int, 3>* t) { std::swap((*t)[1], (*t)[2]); }

/// Every triangle with its own three vertices, as STL stores them.
inline TriangleMesh soup(const TriangleMesh& mesh) {
  TriangleMesh out;
  for (const auto& t : mesh.triangles) {
    const int base = static_cast<int>(out.vertices.size());
    for (const int v : t) out.vertices.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
    out.triangles.push_back({base, base + 1, base + 2});
  }
  return out;
}

// Each triangle's vertex cycle started at its smallest index: the same triangle, facing the
// same way, whichever corner a writer starts from.
inline std::vector<std::array<int, 3>> cycles(const TriangleMesh& mesh) {
  std::vector<std::array<int, 3>> out;
  for (auto t : mesh.triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  return out;
}

}  // namespace fabform::test
