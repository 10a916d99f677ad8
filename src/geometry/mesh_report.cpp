#include "fabform/geometry/mesh_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numeric>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/centroid.h>
#include <CGAL/intersections.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <boost/iterator/function_output_iterator.hpp>

namespace fabform {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;  // exact predicates
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;  // for the few meetings measured
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Face = SurfaceMesh::Face_index;
using Polygon = std::vector<std::size_t>;
using Corners = std::array<Point, 3>;

// ---------------------------------------------------------------------------------------------
// Small helpers

std::size_t at(int index) { return static_cast<std::size_t>(index); }

Point to_point(const Eigen::Vector3d& v) { return Point(v.x(), v.y(), v.z()); }

std::vector<Point> to_points(const TriangleMesh& mesh) {
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) points.push_back(to_point(v));
  return points;
}

bool repeats_index(const std::array<int, 3>& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

std::array<int, 3> sorted(std::array<int, 3> t) {
  std::sort(t.begin(), t.end());
  return t;
}

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  // Returns false when a and b were already joined.
  bool join(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    parent_[b] = a;
    return true;
  }

 private:
  std::vector<std::size_t> parent_;
};

// ---------------------------------------------------------------------------------------------
// Counts on vertices and triangles

int count_bad_indices(const TriangleMesh& mesh) {
  const int n = static_cast<int>(mesh.vertices.size());
  return static_cast<int>(std::count_if(mesh.triangles.begin(), mesh.triangles.end(), [n](const auto& t) {
    return std::any_of(t.begin(), t.end(), [n](int v) { return v < 0 || v >= n; });
  }));
}

int count_isolated_vertices(const TriangleMesh& mesh) {
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (const int v : t) used[at(v)] = 1;
  return static_cast<int>(std::count(used.begin(), used.end(), 0));
}

int count_duplicate_vertices(const TriangleMesh& mesh) {
  std::vector<std::array<double, 3>> coordinates;
  coordinates.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) coordinates.push_back({v.x(), v.y(), v.z()});
  std::sort(coordinates.begin(), coordinates.end());
  return static_cast<int>(coordinates.size() -
                          static_cast<std::size_t>(std::distance(
                              coordinates.begin(), std::unique(coordinates.begin(), coordinates.end()))));
}

void count_degenerate_triangles(const TriangleMesh& mesh, const std::vector<Point>& points, MeshReport* report) {
  for (const auto& t : mesh.triangles) {
    if (repeats_index(t)) {
      ++report->repeated_index_triangles;
      ++report->degenerate_triangles;
    } else if (CGAL::collinear(points[at(t[0])], points[at(t[1])], points[at(t[2])])) {
      ++report->degenerate_triangles;
    }
  }
}

// Indices of the triangles that are first of their vertex set; the others are duplicates.
std::vector<int> first_of_each_vertex_set(const TriangleMesh& mesh) {
  std::vector<std::pair<std::array<int, 3>, int>> keyed;
  keyed.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    keyed.emplace_back(sorted(mesh.triangles[t]), static_cast<int>(t));
  std::sort(keyed.begin(), keyed.end());
  std::vector<int> firsts;
  for (std::size_t k = 0; k < keyed.size(); ++k)
    if (k == 0 || keyed[k].first != keyed[k - 1].first) firsts.push_back(keyed[k].second);
  std::sort(firsts.begin(), firsts.end());
  return firsts;
}

// Component of each triangle (triangles joined through shared vertices), numbered from 0.
std::vector<int> triangle_components(const TriangleMesh& mesh) {
  UnionFind sets(mesh.vertices.size());
  for (const auto& t : mesh.triangles) sets.join(at(t[0]), at(t[1])), sets.join(at(t[0]), at(t[2]));
  std::vector<int> number(mesh.vertices.size(), -1), component;
  int count = 0;
  for (const auto& t : mesh.triangles) {
    int& n = number[sets.find(at(t[0]))];
    if (n < 0) n = count++;
    component.push_back(n);
  }
  return component;
}

// Signed volume (Σ det/6) of each component's triangles.
std::vector<double> component_volumes(const TriangleMesh& mesh, const std::vector<int>& component, int count) {
  std::vector<double> six_volume(at(count), 0.0);
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    six_volume[at(component[k])] += mesh.vertices[at(t[0])].dot(mesh.vertices[at(t[1])].cross(mesh.vertices[at(t[2])]));
  }
  for (double& v : six_volume) v /= 6.0;
  return six_volume;
}

// ---------------------------------------------------------------------------------------------
// Edges: boundary, non-manifold, orientation

struct HalfEdge {
  int low, high;  // vertex indices, low < high
  int triangle;
  bool forward;   // the triangle walks low → high
  bool operator<(const HalfEdge& o) const {
    return std::tie(low, high, triangle) < std::tie(o.low, o.high, o.triangle);
  }
};

// Two triangles across a manifold edge, and whether they walk it the same way.
struct Neighbours {
  int a, b;
  bool same_direction;
};

struct EdgeTopology {
  std::vector<std::pair<int, int>> boundary;  // undirected boundary edges
  std::vector<Neighbours> manifold;           // edges shared by exactly two triangles
};

EdgeTopology edge_topology(const TriangleMesh& mesh, MeshReport* report) {
  std::vector<HalfEdge> halves;
  halves.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (repeats_index(tri)) continue;  // not a surface: its "edges" join nothing
    for (int c = 0; c < 3; ++c) {
      const int from = tri[at(c)], to = tri[at((c + 1) % 3)];
      halves.push_back({std::min(from, to), std::max(from, to), static_cast<int>(t), from < to});
    }
  }
  std::sort(halves.begin(), halves.end());
  EdgeTopology topology;
  for (std::size_t first = 0, last = 0; first < halves.size(); first = last) {
    while (last < halves.size() && halves[last].low == halves[first].low && halves[last].high == halves[first].high)
      ++last;
    ++report->edges;
    const std::size_t uses = last - first;
    if (uses == 1) topology.boundary.emplace_back(halves[first].low, halves[first].high);
    if (uses > 2) ++report->non_manifold_edges;
    if (uses != 2) continue;
    const bool same = halves[first].forward == halves[first + 1].forward;
    if (same) ++report->inconsistent_edges;
    topology.manifold.push_back({halves[first].triangle, halves[first + 1].triangle, same});
  }
  report->boundary_edges = static_cast<int>(topology.boundary.size());
  return topology;
}

// Splits the boundary edges into loops: walks unused edges and closes a loop whenever the walk
// comes back to a vertex on its path, so two loops pinched at one vertex count as two. An open
// chain (only at non-manifold vertices) counts as one; walks start at chain ends first.
int count_boundary_loops(const std::vector<std::pair<int, int>>& edges, std::size_t vertex_count) {
  std::vector<std::vector<int>> incident(vertex_count);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    incident[at(edges[e].first)].push_back(static_cast<int>(e));
    incident[at(edges[e].second)].push_back(static_cast<int>(e));
  }
  std::vector<char> used(edges.size(), 0);
  std::vector<std::size_t> cursor(vertex_count, 0);
  std::vector<int> position(vertex_count, -1);  // index on the current path, or -1
  const auto next_edge = [&](int v) -> int {
    auto& c = cursor[at(v)];
    while (c < incident[at(v)].size() && used[at(incident[at(v)][c])]) ++c;
    return c < incident[at(v)].size() ? incident[at(v)][c] : -1;
  };
  int loops = 0;
  const auto walk_from = [&](int start) {
    std::vector<int> path{start};
    position[at(start)] = 0;
    while (!path.empty()) {
      const int e = next_edge(path.back());
      if (e < 0) {  // dead end: an open chain, if the path holds any edge
        if (path.size() > 1) ++loops;
        for (const int v : path) position[at(v)] = -1;
        return;
      }
      used[at(e)] = 1;
      const int w = edges[at(e)].first == path.back() ? edges[at(e)].second : edges[at(e)].first;
      if (position[at(w)] < 0) {
        position[at(w)] = static_cast<int>(path.size());
        path.push_back(w);
        continue;
      }
      ++loops;  // back on the path: the part of the path after w is a closed loop
      while (path.back() != w) position[at(path.back())] = -1, path.pop_back();
    }
  };
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (incident[v].size() % 2 == 1 && next_edge(static_cast<int>(v)) >= 0) walk_from(static_cast<int>(v));
  for (std::size_t v = 0; v < vertex_count; ++v)
    while (next_edge(static_cast<int>(v)) >= 0) walk_from(static_cast<int>(v));
  return loops;
}

// Whether flipping some triangles can make every manifold edge consistent (two-colouring the
// triangles across manifold edges, an edge asking for "same flip" or "different flip").
bool orientable(std::size_t triangle_count, const std::vector<Neighbours>& manifold) {
  std::vector<std::vector<std::pair<int, bool>>> adjacent(triangle_count);
  for (const auto& n : manifold) {
    adjacent[at(n.a)].emplace_back(n.b, n.same_direction);
    adjacent[at(n.b)].emplace_back(n.a, n.same_direction);
  }
  std::vector<signed char> flip(triangle_count, -1);
  std::vector<int> stack;
  for (std::size_t seed = 0; seed < triangle_count; ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    stack.push_back(static_cast<int>(seed));
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (const auto& [u, same] : adjacent[at(t)]) {
        const signed char wanted = static_cast<signed char>(flip[at(t)] ^ (same ? 1 : 0));
        if (flip[at(u)] < 0) flip[at(u)] = wanted, stack.push_back(u);
        else if (flip[at(u)] != wanted) return false;
      }
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// CGAL: self-intersections and the orientation of closed meshes

// The mesh as a CGAL Surface_mesh: the triangles that are neither repeated-index nor duplicate,
// in the same order as `source` (face k of `mesh` is triangle source[k]).
struct CgalMesh {
  SurfaceMesh mesh;
  std::vector<int> source;
  bool faithful = false;        // same vertices and orientation as the input
  bool same_topology = false;   // no vertex had to be split (non-manifold) to build it
};

std::optional<CgalMesh> to_surface_mesh(const TriangleMesh& input, const std::vector<Point>& points) {
  CgalMesh out;
  std::vector<Polygon> polygons;
  for (const int t : first_of_each_vertex_set(input)) {
    const auto& tri = input.triangles[at(t)];
    if (repeats_index(tri)) continue;
    polygons.push_back({at(tri[0]), at(tri[1]), at(tri[2])});
    out.source.push_back(t);
  }
  std::vector<Point> soup_points = points;
  // An unused vertex would become an isolated Surface_mesh vertex, on which CGAL's volume
  // tests crash; dropping it renumbers vertices only, not faces.
  PMP::remove_isolated_points_in_polygon_soup(soup_points, polygons);
  out.faithful = PMP::is_polygon_soup_a_polygon_mesh(polygons);
  out.same_topology = out.faithful || PMP::orient_polygon_soup(soup_points, polygons);
  if (!out.faithful && !PMP::is_polygon_soup_a_polygon_mesh(polygons)) return std::nullopt;
  PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, out.mesh);
  if (out.mesh.number_of_faces() != polygons.size()) return std::nullopt;
  return out;
}

// Whether two triangles of the input meet other than along what they share, tested on a mesh
// of just the two (for pairs whose shared vertices were split to build the whole mesh).
bool pair_intersects(const TriangleMesh& input, const std::vector<Point>& points, int a, int b) {
  SurfaceMesh pair;
  std::vector<std::pair<int, SurfaceMesh::Vertex_index>> added;
  const auto vertex = [&](int v) {
    for (const auto& [index, handle] : added)
      if (index == v) return handle;
    added.emplace_back(v, pair.add_vertex(points[at(v)]));
    return added.back().second;
  };
  const auto& ta = input.triangles[at(a)];
  const auto& tb = input.triangles[at(b)];
  pair.add_face(vertex(ta[0]), vertex(ta[1]), vertex(ta[2]));
  if (pair.add_face(vertex(tb[0]), vertex(tb[1]), vertex(tb[2])) == SurfaceMesh::null_face())
    pair.add_face(vertex(tb[0]), vertex(tb[2]), vertex(tb[1]));
  std::vector<std::pair<Face, Face>> found;
  PMP::self_intersections(pair, std::back_inserter(found));
  return std::any_of(found.begin(), found.end(), [](const auto& f) { return f.first != f.second; });
}

bool share_vertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return std::any_of(a.begin(), a.end(), [&](int v) { return std::find(b.begin(), b.end(), v) != b.end(); });
}

// Coplanar triangles whose interiors are apart: an edge line of one has the other wholly on
// its far side (or on it). Exact.
bool separated_in_plane(const Corners& a, const Corners& b) {
  const auto separates = [](const Corners& t, const Corners& u) {
    for (int e = 0; e < 3; ++e) {
      const Point &p = t[at(e)], &q = t[at((e + 1) % 3)], &r = t[at((e + 2) % 3)];
      if (std::none_of(u.begin(), u.end(), [&](const Point& s) { return CGAL::coplanar_orientation(p, q, r, s) == CGAL::POSITIVE; }))
        return true;
    }
    return false;
  };
  return separates(a, b) || separates(b, a);
}

// Distance from x (in or near the triangle's plane) to the line through the triangle's edge e.
double edge_line_distance(const Corners& t, int e, const Point& x) {
  const Kernel::Vector_3 edge = t[at((e + 1) % 3)] - t[at(e)];
  return std::sqrt(CGAL::to_double(CGAL::cross_product(edge, x - t[at(e)]).squared_length() / edge.squared_length()));
}

// How far into the triangle a point of it lies: its distance to the nearest edge line.
double depth_in(const Corners& t, const Point& x) {
  return std::min({edge_line_distance(t, 0, x), edge_line_distance(t, 1, x), edge_line_distance(t, 2, x)});
}

// The deepest a segment inside the triangle goes: each edge-line distance is affine along it,
// so their minimum is concave and peaks at an end or where two of them are equal.
double depth_in(const Corners& t, const Point& from, const Point& to) {
  std::array<double, 3> d0{}, d1{};
  for (int e = 0; e < 3; ++e) d0[at(e)] = edge_line_distance(t, e, from), d1[at(e)] = edge_line_distance(t, e, to);
  double deepest = std::max(depth_in(t, from), depth_in(t, to));
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const double slope = (d1[at(i)] - d0[at(i)]) - (d1[at(j)] - d0[at(j)]);
      if (slope == 0.0) continue;
      const double s = (d0[at(j)] - d0[at(i)]) / slope;
      if (s > 0.0 && s < 1.0) deepest = std::max(deepest, depth_in(t, from + s * (to - from)));
    }
  return deepest;
}

// How far the meeting of two triangles reaches inside either of them, away from its edges:
// zero (up to rounding) when they only touch along their boundaries. Exact constructions, since
// CAD cracks cross by 1e-16 and a double construction finds no intersection at all.
double meeting_depth(const Corners& a, const Corners& b) {
  const CGAL::Cartesian_converter<Kernel, ExactKernel> to_exact;
  const CGAL::Cartesian_converter<ExactKernel, Kernel> to_double;
  const auto meeting = CGAL::intersection(ExactKernel::Triangle_3(to_exact(a[0]), to_exact(a[1]), to_exact(a[2])),
                                          ExactKernel::Triangle_3(to_exact(b[0]), to_exact(b[1]), to_exact(b[2])));
  if (!meeting) return 0.0;
  std::vector<Point> corners_of_meeting;
  if (const auto* point = boost::get<ExactKernel::Point_3>(&*meeting)) {
    const Point x = to_double(*point);
    return std::max(depth_in(a, x), depth_in(b, x));
  }
  if (const auto* segment = boost::get<ExactKernel::Segment_3>(&*meeting)) {
    const Point from = to_double(segment->source()), to = to_double(segment->target());
    return std::max(depth_in(a, from, to), depth_in(b, from, to));
  }
  // Coplanar overlap (a triangle or a polygon): its corners and its centre.
  if (const auto* triangle = boost::get<ExactKernel::Triangle_3>(&*meeting))
    for (int c = 0; c < 3; ++c) corners_of_meeting.push_back(to_double(triangle->vertex(c)));
  if (const auto* polygon = boost::get<std::vector<ExactKernel::Point_3>>(&*meeting))
    for (const auto& corner : *polygon) corners_of_meeting.push_back(to_double(corner));
  if (corners_of_meeting.empty()) return 0.0;
  corners_of_meeting.push_back(CGAL::centroid(corners_of_meeting.begin(), corners_of_meeting.end()));
  double deepest = 0.0;
  for (const Point& x : corners_of_meeting) deepest = std::max({deepest, depth_in(a, x), depth_in(b, x)});
  return deepest;
}

// Two triangles that CGAL finds meeting (other than along what they share) but that only
// touch along their boundaries: the edges of a CAD crack or a T-junction lying along each other
// without sharing vertices, up to `tolerance` (the float rounding of the export).
bool only_touch(const Corners& a, const Corners& b, double tolerance) {
  const bool coplanar = std::all_of(b.begin(), b.end(), [&](const Point& p) { return CGAL::coplanar(a[0], a[1], a[2], p); });
  if (coplanar && separated_in_plane(a, b)) return true;
  return meeting_depth(a, b) <= tolerance;
}

Corners corners(const TriangleMesh& mesh, const std::vector<Point>& points, int triangle) {
  const auto& t = mesh.triangles[at(triangle)];
  return {points[at(t[0])], points[at(t[1])], points[at(t[2])]};
}

struct CapReached {};

void find_self_intersections(const TriangleMesh& input, const std::vector<Point>& points, const CgalMesh& cgal,
                             const InspectOptions& options, MeshReport* report) {
  report->self_intersections_checked = true;
  const int cap = std::max(options.max_self_intersection_pairs, 1);
  const double tolerance = options.touch_tolerance * report->box.diagonal();
  const std::function<void(const std::pair<Face, Face>&)> classify = [&](const std::pair<Face, Face>& pair) {
    if (pair.first == pair.second) return;  // a zero-area face, counted as degenerate
    const int a = cgal.source[pair.first.idx()], b = cgal.source[pair.second.idx()];
    if (only_touch(corners(input, points, a), corners(input, points, b), tolerance)) {
      ++report->touching_pairs;
      return;
    }
    if (!cgal.same_topology && share_vertex(input.triangles[at(a)], input.triangles[at(b)]) &&
        !pair_intersects(input, points, a, b))
      return;
    if (++report->self_intersecting_pairs >= cap) throw CapReached{};
  };
  try {
    PMP::self_intersections(cgal.mesh, boost::make_function_output_iterator(classify));
    report->self_intersections_complete = true;
  } catch (const CapReached&) {
    report->self_intersection_note = "stopped counting at " + std::to_string(cap) + " pairs";
  }
}

// Closed and consistent. CGAL decides whether the mesh bounds a volume (a cavity inside a solid
// points into the cavity) when it is a valid surface without self-intersections. Otherwise
// each component's signed volume does: all positive is outward (nested solids that each point
// out are fine for contact, which only meets the outermost), all negative inward.
MeshOrientation closed_orientation(const std::optional<CgalMesh>& cgal, const MeshReport& report,
                                   const std::vector<double>& volumes) {
  const bool trusted = cgal && cgal->faithful && CGAL::is_closed(cgal->mesh) && report.self_intersections_checked &&
                       report.self_intersections_complete && report.self_intersecting_pairs == 0 &&
                       report.touching_pairs == 0;
  // does_bound_a_volume accepts a whole mesh turned inside out too (its nesting is consistent),
  // so the sign of the enclosed volume tells outward from inward.
  if (trusted && PMP::does_bound_a_volume(cgal->mesh))
    return report.signed_volume > 0.0 ? MeshOrientation::outward : MeshOrientation::inward;
  const auto positive = std::count_if(volumes.begin(), volumes.end(), [](double v) { return v > 0.0; });
  if (positive == static_cast<std::ptrdiff_t>(volumes.size())) return MeshOrientation::outward;
  return positive == 0 ? MeshOrientation::inward : MeshOrientation::mixed;
}

}  // namespace

std::string to_string(MeshOrientation orientation) {
  switch (orientation) {
    case MeshOrientation::consistent_open: return "consistent (open: no inside or outside)";
    case MeshOrientation::outward: return "consistent, outward";
    case MeshOrientation::inward: return "consistent, inward (inverted)";
    case MeshOrientation::mixed: return "consistent, but some closed components point inward";
    case MeshOrientation::inconsistent: return "inconsistent";
    case MeshOrientation::non_orientable: return "non-orientable";
  }
  return "unknown";
}

bool MeshReport::usable_for_contact(std::string* why) const {
  const auto no = [why](std::string reason) {
    if (why) *why = std::move(reason);
    return false;
  };
  if (triangles == 0) return no("the mesh has no triangles");
  if (bad_indices > 0) return no(std::to_string(bad_indices) + " triangles name a vertex that does not exist");
  if (degenerate_triangles == triangles) return no("every triangle is degenerate (zero area)");
  switch (orientation) {
    case MeshOrientation::inconsistent:
      return no("inconsistent orientation: " + std::to_string(inconsistent_edges) +
                " edges are shared by triangles facing opposite ways");
    case MeshOrientation::non_orientable:
      return no("the surface cannot be oriented consistently (non-orientable)");
    case MeshOrientation::inward:
      return no("the faces point inward (closed mesh, negative enclosed volume)");
    case MeshOrientation::mixed: return no("some closed components have their faces pointing inward");
    default: return true;
  }
}

bool MeshReport::repairable() const {
  return triangles > degenerate_triangles && bad_indices == 0 &&
         (orientation == MeshOrientation::inconsistent || orientation == MeshOrientation::inward ||
          orientation == MeshOrientation::mixed);
}

std::string MeshReport::contact_refusal() const {
  std::string why;
  if (usable_for_contact(&why)) return "";
  if (orientation == MeshOrientation::inward || orientation == MeshOrientation::mixed)
    why += ": contact would take its outside for inside";
  if (repairable()) why += "; fabform check MESH --repair OUT.obj fixes it";
  return why;
}

std::vector<std::string> MeshReport::contact_warnings() const {
  std::vector<std::string> warnings;
  if (self_intersecting_pairs > 0)
    warnings.push_back((self_intersections_complete ? "" : "at least ") + std::to_string(self_intersecting_pairs) +
                       " pairs of triangles cross each other (self-intersections): contact near them may be wrong");
  return warnings;
}

MeshReport inspect_mesh(const TriangleMesh& mesh, const InspectOptions& options) {
  MeshReport report;
  report.vertices = static_cast<int>(mesh.vertices.size());
  report.triangles = static_cast<int>(mesh.triangles.size());
  report.box = bounding_box(mesh.vertices);
  report.bad_indices = count_bad_indices(mesh);
  if (report.bad_indices > 0 || mesh.triangles.empty()) return report;

  const std::vector<Point> points = to_points(mesh);
  report.isolated_vertices = count_isolated_vertices(mesh);
  report.duplicate_vertices = count_duplicate_vertices(mesh);
  count_degenerate_triangles(mesh, points, &report);
  report.duplicate_triangles = report.triangles - static_cast<int>(first_of_each_vertex_set(mesh).size());
  const std::vector<int> component = triangle_components(mesh);
  report.components = 1 + *std::max_element(component.begin(), component.end());
  const std::vector<double> volumes = component_volumes(mesh, component, report.components);
  report.signed_volume = std::accumulate(volumes.begin(), volumes.end(), 0.0);

  const EdgeTopology topology = edge_topology(mesh, &report);
  report.boundary_loops = count_boundary_loops(topology.boundary, mesh.vertices.size());
  report.closed = report.edges > 0 && report.boundary_edges == 0;

  std::optional<CgalMesh> cgal;
  if (!options.self_intersections) {
    report.self_intersection_note = "not checked";
  } else if (report.triangles > options.max_self_intersection_triangles) {
    report.self_intersection_note = "not checked: more than " + std::to_string(options.max_self_intersection_triangles) + " triangles";
  } else if (!(cgal = to_surface_mesh(mesh, points))) {
    report.self_intersection_note = "not checked: the triangles do not form a surface CGAL can build";
  } else {
    find_self_intersections(mesh, points, *cgal, options, &report);
  }

  if (!orientable(mesh.triangles.size(), topology.manifold)) report.orientation = MeshOrientation::non_orientable;
  else if (report.inconsistent_edges > 0) report.orientation = MeshOrientation::inconsistent;
  else if (!report.closed) report.orientation = MeshOrientation::consistent_open;
  else report.orientation = closed_orientation(cgal, report, volumes);
  return report;
}

}  // namespace fabform
