#include "fabform/geometry/mesh_repair.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

namespace fabform {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;  // exact predicates
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Face = SurfaceMesh::Face_index;
using Polygon = std::vector<std::size_t>;
using Cycle = std::array<std::size_t, 3>;

struct Soup {
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

Soup to_soup(const TriangleMesh& mesh) {
  Soup soup;
  for (const auto& v : mesh.vertices) soup.points.emplace_back(v.x(), v.y(), v.z());
  const int n = static_cast<int>(mesh.vertices.size());
  for (const auto& t : mesh.triangles) {
    if (std::any_of(t.begin(), t.end(), [n](int v) { return v < 0 || v >= n; }))
      throw std::invalid_argument("a triangle names a vertex that does not exist");
    soup.polygons.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                             static_cast<std::size_t>(t[2])});
  }
  return soup;
}

// Zero area: a repeated vertex or three collinear points (exact predicate).
int remove_degenerate(Soup* soup) {
  const auto degenerate = [&](const Polygon& p) {
    return p[0] == p[1] || p[1] == p[2] || p[2] == p[0] ||
           CGAL::collinear(soup->points[p[0]], soup->points[p[1]], soup->points[p[2]]);
  };
  const auto end = std::remove_if(soup->polygons.begin(), soup->polygons.end(), degenerate);
  const auto removed = static_cast<int>(soup->polygons.end() - end);
  soup->polygons.erase(end, soup->polygons.end());
  return removed;
}

// The same cycle of vertices whatever corner it starts from.
Cycle canonical(Cycle c) {
  std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
  return c;
}

double signed_volume(const SurfaceMesh& mesh, const std::vector<Face>& faces) {
  double six_volume = 0.0;
  for (const Face f : faces) {
    const auto h = mesh.halfedge(f);
    const auto a = mesh.point(mesh.source(h)) - CGAL::ORIGIN;
    const auto b = mesh.point(mesh.target(h)) - CGAL::ORIGIN;
    const auto c = mesh.point(mesh.target(mesh.next(h))) - CGAL::ORIGIN;
    six_volume += CGAL::scalar_product(a, CGAL::cross_product(b, c));
  }
  return six_volume / 6.0;
}

// Per vertex of `mesh`, its index in `before`. orient_polygon_soup splits vertices where the
// surface is not a manifold; the copies sit at their original's position, and `before` holds
// each position once (duplicates are merged first).
std::vector<std::size_t> original_vertices(const SurfaceMesh& mesh, const Soup& before) {
  std::map<Point, std::size_t> index;
  for (std::size_t i = 0; i < before.points.size(); ++i) index.emplace(before.points[i], i);
  std::vector<std::size_t> original(mesh.number_of_vertices());
  for (const auto v : mesh.vertices()) original[v.idx()] = index.at(mesh.point(v));
  return original;
}

// Face f's corners as indices into `before`.
Cycle corners(const SurfaceMesh& mesh, Face f, const std::vector<std::size_t>& original) {
  Cycle c{};
  std::size_t k = 0;
  for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) c[k++] = original[v.idx()];
  return c;
}

// Per face, whether its vertex cycle runs the other way round from the same polygon of
// `before` (face k is polygon k).
std::vector<char> reversed_faces(const SurfaceMesh& mesh, const Soup& before) {
  const std::vector<std::size_t> original = original_vertices(mesh, before);
  std::vector<char> reversed(mesh.number_of_faces(), 0);
  for (const Face f : mesh.faces()) {
    const Polygon& was = before.polygons[f.idx()];
    reversed[f.idx()] = canonical(corners(mesh, f, original)) != canonical(Cycle{was[0], was[1], was[2]});
  }
  return reversed;
}

// Chooses each component's side once its triangles agree: a closed mesh without
// self-intersections is oriented to bound a volume (a cavity inside a solid points into the
// cavity); otherwise a closed component points outward (positive volume) and an open one keeps
// the orientation most of its triangles had in the input.
void orient_components(SurfaceMesh* mesh, const Soup& before) {
  if (CGAL::is_closed(*mesh) && !PMP::does_self_intersect(*mesh)) {
    PMP::orient_to_bound_a_volume(*mesh);
    return;
  }
  auto component = mesh->add_property_map<Face, std::size_t>("f:component", 0).first;
  const std::size_t count = PMP::connected_components(*mesh, component);
  std::vector<std::vector<Face>> faces(count);
  std::vector<char> open(count, 0);
  for (const Face f : mesh->faces()) {
    faces[component[f]].push_back(f);
    for (const auto h : CGAL::halfedges_around_face(mesh->halfedge(f), *mesh))
      if (mesh->is_border(mesh->opposite(h))) open[component[f]] = 1;
  }
  mesh->remove_property_map(component);
  const std::vector<char> reversed = reversed_faces(*mesh, before);
  for (std::size_t c = 0; c < count; ++c) {
    const auto flipped = std::count_if(faces[c].begin(), faces[c].end(), [&](Face f) { return reversed[f.idx()] != 0; });
    const bool turn = open[c] ? 2 * static_cast<std::size_t>(flipped) > faces[c].size() : signed_volume(*mesh, faces[c]) < 0.0;
    if (turn) PMP::reverse_face_orientations(faces[c], *mesh);
  }
}

// The oriented faces over the vertices of `before`: the vertices orient_polygon_soup split are
// joined again. A file cannot keep two vertices at one position apart (every reader, fabform's
// among them, joins them), so a split would promise a manifold surface that the written file
// is not; its non-manifold edges stay, and are reported.
TriangleMesh to_triangle_mesh(const SurfaceMesh& mesh, const Soup& before) {
  TriangleMesh out;
  for (const Point& p : before.points) out.vertices.emplace_back(p.x(), p.y(), p.z());
  const std::vector<std::size_t> original = original_vertices(mesh, before);
  for (const Face f : mesh.faces()) {
    const Cycle c = corners(mesh, f, original);
    out.triangles.push_back({static_cast<int>(c[0]), static_cast<int>(c[1]), static_cast<int>(c[2])});
  }
  return out;
}

}  // namespace

bool RepairResult::changed() const { return !changes().empty(); }

std::vector<std::string> RepairResult::changes() const {
  std::vector<std::string> lines;
  const auto add = [&](int n, const std::string& what) {
    if (n > 0) lines.push_back(std::to_string(n) + " " + what);
  };
  add(merged_vertices, "duplicate vertices merged (same position as another)");
  add(removed_degenerate, "degenerate (zero-area) triangles dropped");
  add(removed_duplicate, "duplicate triangles dropped (same vertices as another)");
  add(removed_isolated_vertices, "unused vertices dropped");
  add(reversed_triangles, "triangles flipped to a consistent orientation, outward where closed");
  return lines;
}

RepairResult repair_mesh(const TriangleMesh& mesh) {
  RepairResult result;
  Soup soup = to_soup(mesh);
  // The steps of PMP::repair_polygon_soup, one at a time so that each can be counted, with
  // degenerate triangles (which it keeps when their points are distinct) dropped as well.
  result.merged_vertices = static_cast<int>(PMP::merge_duplicate_points_in_polygon_soup(soup.points, soup.polygons));
  result.removed_degenerate = remove_degenerate(&soup);
  result.removed_duplicate = static_cast<int>(PMP::merge_duplicate_polygons_in_polygon_soup(soup.points, soup.polygons));
  result.removed_isolated_vertices = static_cast<int>(PMP::remove_isolated_points_in_polygon_soup(soup.points, soup.polygons));

  if (soup.polygons.empty()) return result;

  const Soup before_orientation = soup;
  PMP::orient_polygon_soup(soup.points, soup.polygons);
  SurfaceMesh surface;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, surface);
  orient_components(&surface, before_orientation);
  const std::vector<char> reversed = reversed_faces(surface, before_orientation);
  result.reversed_triangles = static_cast<int>(std::count(reversed.begin(), reversed.end(), 1));
  result.mesh = to_triangle_mesh(surface, before_orientation);
  return result;
}

}  // namespace fabform
