#include "fabform/analysis/self_intersections.hpp"

#include <iterator>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include "fabform/model/seam.hpp"

namespace fabform {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// The fabric as a surface mesh, one vertex per sewn group. A triangle the mesh cannot take as a
// manifold neighbour (a fold pinched onto itself along a seam) gets vertices of its own: it is
// still checked against every other, and only its shared corners go unrecognised.
Mesh formed_mesh(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const std::vector<int> sewn = sewn_representatives(model);
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertex(x.size());
  const auto point = [&](int n) {
    const Eigen::Vector3d& p = x[static_cast<std::size_t>(n)];
    return Kernel::Point_3(p.x(), p.y(), p.z());
  };
  for (std::size_t k = 0; k < x.size(); ++k)
    if (sewn[k] == static_cast<int>(k)) vertex[k] = mesh.add_vertex(point(static_cast<int>(k)));
  for (std::size_t k = 0; k < x.size(); ++k) vertex[k] = vertex[static_cast<std::size_t>(sewn[k])];
  for (const auto& [a, b, c] : face_triangles(model.fabric.faces())) {
    const auto va = vertex[static_cast<std::size_t>(a)], vb = vertex[static_cast<std::size_t>(b)],
               vc = vertex[static_cast<std::size_t>(c)];
    if (mesh.add_face(va, vb, vc) == Mesh::null_face())
      mesh.add_face(mesh.add_vertex(point(a)), mesh.add_vertex(point(b)), mesh.add_vertex(point(c)));
  }
  return mesh;
}

}  // namespace

int count_self_intersections(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const Mesh mesh = formed_mesh(model, x);
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(pairs));
  return static_cast<int>(pairs.size());
}

}  // namespace fabform
