// inspect_mesh on hand-built meshes whose answers are known (a unit cube, opened, flipped,
// soup-like, with degenerate, duplicate and crossing triangles) and on the two shipped molds,
// whose boundary loops are counted here independently (union-find over boundary edges).
#include "fabform/geometry/mesh_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

#include "fabform/io/mesh_reader.hpp"
#include "support/shapes.hpp"
#include "test_paths.hpp"

namespace fabform::mesh_report_test {
namespace {

using test::cube;
using test::flip;
using test::soup;
using V = Eigen::Vector3d;

TriangleMesh flipped(TriangleMesh mesh) {
  for (auto& t : mesh.triangles) flip(&t);
  return mesh;
}

TriangleMesh joined(TriangleMesh a, const TriangleMesh& b) {
  const int base = static_cast<int>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  return a;
}

TriangleMesh triangles(const std::vector<std::array<V, 3>>& corners) {
  TriangleMesh mesh;
  for (const auto& c : corners) {
    const int base = static_cast<int>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), c.begin(), c.end());
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// The cube and what can go wrong with it

TEST(MeshReport, ClosedCubeIsClosedOutwardAndUsable) {
  const MeshReport r = inspect_mesh(cube());
  EXPECT_EQ(r.vertices, 8);
  EXPECT_EQ(r.triangles, 12);
  EXPECT_EQ(r.edges, 18);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.boundary_loops, 0);
  EXPECT_EQ(r.non_manifold_edges, 0);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.inconsistent_edges, 0);
  EXPECT_EQ(r.orientation, MeshOrientation::outward);
  EXPECT_NEAR(r.signed_volume, 1.0, 1e-15);
  EXPECT_EQ(r.box.min, V(0, 0, 0));
  EXPECT_EQ(r.box.max, V(1, 1, 1));
  EXPECT_EQ(r.degenerate_triangles + r.duplicate_triangles + r.duplicate_vertices + r.isolated_vertices, 0);
  EXPECT_TRUE(r.self_intersections_checked);
  EXPECT_TRUE(r.self_intersections_complete);
  EXPECT_EQ(r.self_intersecting_pairs, 0);
  EXPECT_EQ(r.touching_pairs, 0);
  EXPECT_TRUE(r.usable_for_contact());
  EXPECT_TRUE(r.contact_warnings().empty());
}

TEST(MeshReport, CubeWithoutItsTopHasOneBoundaryLoopAndIsUsable) {
  TriangleMesh mesh = cube();
  mesh.triangles.erase(mesh.triangles.begin() + 2, mesh.triangles.begin() + 4);  // z = 1
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.boundary_edges, 4);
  EXPECT_EQ(r.boundary_loops, 1);
  EXPECT_EQ(r.orientation, MeshOrientation::consistent_open);
  EXPECT_TRUE(r.usable_for_contact());
  EXPECT_TRUE(r.contact_warnings().empty()) << "an open mold is fine for contact";
}

TEST(MeshReport, FlippedCubeIsInwardAndNotUsable) {
  const MeshReport r = inspect_mesh(flipped(cube()));
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.inconsistent_edges, 0);
  EXPECT_EQ(r.orientation, MeshOrientation::inward);
  EXPECT_NEAR(r.signed_volume, -1.0, 1e-15);
  std::string why;
  EXPECT_FALSE(r.usable_for_contact(&why));
  EXPECT_NE(why.find("inward"), std::string::npos) << why;
  EXPECT_TRUE(r.repairable());
  EXPECT_NE(r.contact_refusal().find("point inward (closed mesh, negative enclosed volume): contact would take its outside for inside; "
                                         "fabform check MESH --repair"),
            std::string::npos) << r.contact_refusal();
  EXPECT_TRUE(r.contact_warnings().empty());
}

TEST(MeshReport, CubeWithOneFlippedTriangleIsInconsistent) {
  TriangleMesh mesh = cube();
  flip(&mesh.triangles[5]);
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.inconsistent_edges, 3);  // all three edges of the flipped triangle
  EXPECT_EQ(r.orientation, MeshOrientation::inconsistent);
  EXPECT_FALSE(r.usable_for_contact());
  EXPECT_TRUE(r.repairable());
  EXPECT_EQ(r.contact_refusal(), "inconsistent orientation: 3 edges are shared by triangles facing opposite ways; "
                                 "fabform check MESH --repair OUT.obj fixes it");
}

TEST(MeshReport, MoebiusBandIsNonOrientableAndNotRepairable) {
  // A strip of 8 quads round a circle, its ends joined with a half twist.
  TriangleMesh band;
  const int n = 8;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * 3.14159265358979 * k / n, twist = a / 2.0;
    const V centre(std::cos(a), std::sin(a), 0.0), across(std::cos(twist) * std::cos(a), std::cos(twist) * std::sin(a), std::sin(twist));
    band.vertices.push_back(centre - 0.3 * across);
    band.vertices.push_back(centre + 0.3 * across);
  }
  for (int k = 0; k < n; ++k) {
    const int a0 = 2 * k, a1 = 2 * k + 1;
    const bool last = k == n - 1;
    const int b0 = last ? 1 : 2 * k + 2, b1 = last ? 0 : 2 * k + 3;  // the half twist swaps the sides
    band.triangles.push_back({a0, b0, b1});
    band.triangles.push_back({a0, b1, a1});
  }
  const MeshReport r = inspect_mesh(band);
  EXPECT_EQ(r.orientation, MeshOrientation::non_orientable);
  EXPECT_EQ(r.boundary_loops, 1);  // a Möbius band has one edge
  EXPECT_EQ(r.boundary_edges, 2 * n);
  EXPECT_FALSE(r.usable_for_contact());
  EXPECT_FALSE(r.repairable());
}

TEST(MeshReport, CountsDegenerateAndDuplicateTriangles) {
  TriangleMesh mesh = cube();
  mesh.triangles.push_back({0, 0, 1});  // repeated vertex
  mesh.triangles.push_back({mesh.triangles[0][0], mesh.triangles[0][2], mesh.triangles[0][1]});  // duplicate, reversed
  mesh.triangles.push_back(mesh.triangles[1]);  // duplicate, same way round
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_EQ(r.degenerate_triangles, 1);
  EXPECT_EQ(r.repeated_index_triangles, 1);
  EXPECT_EQ(r.duplicate_triangles, 2);
  EXPECT_EQ(r.non_manifold_edges, 5);  // the two duplicated triangles' edges (their diagonal shared)
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.self_intersecting_pairs, 0) << "duplicates are reported as duplicates, not as crossings";
}

TEST(MeshReport, ZeroAreaTriangleWithDistinctVerticesIsDegenerate) {
  TriangleMesh mesh = cube();
  mesh.vertices.push_back({0.5, 0.0, 0.0});  // the middle of edge 0–1
  mesh.triangles.push_back({0, 8, 1});
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_EQ(r.degenerate_triangles, 1);
  EXPECT_EQ(r.repeated_index_triangles, 0);
  EXPECT_EQ(r.self_intersecting_pairs, 0);
}

TEST(MeshReport, StlLikeSoupHasDuplicateVerticesAndNoSharedEdges) {
  const MeshReport r = inspect_mesh(soup(cube()));
  EXPECT_EQ(r.vertices, 36);
  EXPECT_EQ(r.duplicate_vertices, 28);
  EXPECT_EQ(r.boundary_edges, 36);
  EXPECT_EQ(r.boundary_loops, 12);
  EXPECT_EQ(r.components, 12);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.self_intersecting_pairs, 0);
  EXPECT_GT(r.touching_pairs, 0) << "neighbours meet along edges they do not share";
}

TEST(MeshReport, UnusedVerticesAndBadIndices) {
  TriangleMesh mesh = cube();
  mesh.vertices.push_back({5, 5, 5});
  EXPECT_EQ(inspect_mesh(mesh).isolated_vertices, 1);
  mesh.triangles.push_back({0, 1, 42});
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_EQ(r.bad_indices, 1);
  EXPECT_FALSE(r.usable_for_contact());
  EXPECT_FALSE(r.repairable());
}

TEST(MeshReport, EmptyMeshIsNotUsable) {
  std::string why;
  EXPECT_FALSE(inspect_mesh(TriangleMesh{}).usable_for_contact(&why));
  EXPECT_NE(why.find("no triangles"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Components and nesting

TEST(MeshReport, TwoSeparateCubesAreTwoComponents) {
  const MeshReport r = inspect_mesh(joined(cube(), cube(V(3, 0, 0))));
  EXPECT_EQ(r.components, 2);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.orientation, MeshOrientation::outward);
  EXPECT_NEAR(r.signed_volume, 2.0, 1e-14);
}

TEST(MeshReport, OneOfTwoCubesInvertedIsMixed) {
  const MeshReport r = inspect_mesh(joined(cube(), flipped(cube(V(3, 0, 0)))));
  EXPECT_EQ(r.orientation, MeshOrientation::mixed);
  EXPECT_NEAR(r.signed_volume, 0.0, 1e-14);
  EXPECT_FALSE(r.usable_for_contact());
}

TEST(MeshReport, CavityPointingIntoItselfBoundsAVolume) {
  // A hollow block: the inner surface's normals point into the cavity, out of the material.
  const MeshReport r = inspect_mesh(joined(cube(V(-1, -1, -1), 3.0), flipped(cube())));
  EXPECT_EQ(r.components, 2);
  EXPECT_EQ(r.orientation, MeshOrientation::outward);
  EXPECT_NEAR(r.signed_volume, 26.0, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Self-intersections: crossings count, touching along unshared edges does not

const std::array<V, 3> kFloor{V(0, 0, 0), V(2, 0, 0), V(0, 2, 0)};

TEST(MeshReport, TwoCrossingTrianglesAreOneSelfIntersection) {
  // A vertical triangle in the plane y = 0.5 piercing the floor's interior.
  const MeshReport r = inspect_mesh(triangles({kFloor, {V(0.2, 0.5, -1), V(0.2, 0.5, 1), V(1.0, 0.5, 0.3)}}));
  EXPECT_EQ(r.components, 2);
  EXPECT_EQ(r.self_intersecting_pairs, 1);
  EXPECT_EQ(r.touching_pairs, 0);
  EXPECT_TRUE(r.self_intersections_complete);
  EXPECT_TRUE(r.usable_for_contact()) << "a warning, not a reason to refuse";
  EXPECT_EQ(r.contact_refusal(), "");
  ASSERT_EQ(r.contact_warnings().size(), 1u);
  EXPECT_NE(r.contact_warnings()[0].find("cross"), std::string::npos);
}

TEST(MeshReport, OverlappingCoplanarTrianglesIntersect) {
  const MeshReport r = inspect_mesh(triangles({kFloor, {V(0.5, 0.5, 0), V(1.5, 0.2, 0), V(0.4, 1.2, 0)}}));
  EXPECT_EQ(r.self_intersecting_pairs, 1);
}

TEST(MeshReport, TJunctionsOnlyTouch) {
  const MeshReport r = inspect_mesh(triangles({
      kFloor,
      {V(0.5, 0, 0), V(1.5, 0, 0), V(1, -1, 0)},   // coplanar, below the floor's edge y = 0
      {V(0.5, 0, 0), V(1, 0, -1), V(1.5, 0, 0)},   // a wall hanging from that edge
  }));
  EXPECT_EQ(r.self_intersecting_pairs, 0);
  EXPECT_EQ(r.touching_pairs, 3);
}

TEST(MeshReport, CrackCrossingByRoundingOnlyTouchesButARealDipCrosses) {
  // A wall leaning over the floor whose foot, along the floor's edge, dips below it: by 1e-13
  // (an export's rounding; featuretype.STL's walls dip 2.7e-16 in) it touches; by 1e-3 it crosses.
  const auto wall = [](double dip) {
    return std::array<V, 3>{V(0.5, 0, -dip), V(1.5, 0, -dip), V(1, 1, 1)};
  };
  const MeshReport rounding = inspect_mesh(triangles({kFloor, wall(1e-13)}));
  EXPECT_EQ(rounding.self_intersecting_pairs, 0);
  EXPECT_EQ(rounding.touching_pairs, 1);
  const MeshReport dip = inspect_mesh(triangles({kFloor, wall(1e-3)}));
  EXPECT_EQ(dip.self_intersecting_pairs, 1);
}

TEST(MeshReport, SelfIntersectionCountStopsAtTheCapAndSaysSo) {
  std::vector<std::array<V, 3>> fan{kFloor};
  for (int k = 0; k < 20; ++k) {
    const double y = 0.05 + 0.05 * k;
    fan.push_back({V(0.1, y, -1), V(0.1, y, 1), V(0.6, y, 0.2)});
  }
  InspectOptions options;
  options.max_self_intersection_pairs = 5;
  const MeshReport r = inspect_mesh(triangles(fan), options);
  EXPECT_EQ(r.self_intersecting_pairs, 5);
  EXPECT_FALSE(r.self_intersections_complete);
  EXPECT_NE(r.self_intersection_note.find("stopped"), std::string::npos);
  EXPECT_EQ(inspect_mesh(triangles(fan)).self_intersecting_pairs, 20);
  options.self_intersections = false;
  EXPECT_FALSE(inspect_mesh(triangles(fan), options).self_intersections_checked);
}

TEST(MeshReport, SphereFromTheTestShapesIsClosedAndOutward) {
  const MeshReport r = inspect_mesh(test::uv_sphere(V(0, 0, 0), 1.0, 12, 24));
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.orientation, MeshOrientation::outward);
  EXPECT_EQ(r.self_intersecting_pairs + r.touching_pairs, 0);
}

// ---------------------------------------------------------------------------------------------
// The shipped molds

// Boundary loops counted independently: connected components of the boundary-edge graph,
// valid as a loop count when every boundary vertex has exactly two boundary edges.
struct BoundaryCount {
  int edges = 0;
  int loops = 0;
  bool every_vertex_on_two = true;
};

BoundaryCount count_boundary(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) ++uses[std::minmax(t[static_cast<std::size_t>(c)], t[static_cast<std::size_t>((c + 1) % 3)])];
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int v) {
    while (parent[static_cast<std::size_t>(v)] != v) v = parent[static_cast<std::size_t>(v)];
    return v;
  };
  std::map<int, int> degree;
  BoundaryCount count;
  for (const auto& [edge, n] : uses) {
    if (n != 1) continue;
    ++count.edges;
    ++degree[edge.first], ++degree[edge.second];
    parent[static_cast<std::size_t>(find(edge.first))] = find(edge.second);
  }
  std::set<int> roots;
  for (const auto& [v, d] : degree) {
    roots.insert(find(v));
    if (d != 2) count.every_vertex_on_two = false;
  }
  count.loops = static_cast<int>(roots.size());
  return count;
}

TEST(MeshReport, FeaturetypeMold) {
  const TriangleMesh mesh = read_mesh(test::source_path("molds/trimesh_featuretype.STL"));
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_EQ(r.triangles, 3476);
  EXPECT_EQ(r.vertices, 2010);
  EXPECT_EQ(r.boundary_edges, 576);  // molds/README.md: CAD tessellation cracks
  const BoundaryCount independent = count_boundary(mesh);
  ASSERT_TRUE(independent.every_vertex_on_two);
  EXPECT_EQ(independent.edges, 576);
  EXPECT_EQ(r.boundary_loops, independent.loops);
  EXPECT_EQ(r.boundary_loops, 16);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.non_manifold_edges, 0);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.orientation, MeshOrientation::consistent_open);
  EXPECT_NEAR(r.signed_volume, 11.6, 0.05);  // molds/README.md: +11.6 in³, outward
  EXPECT_EQ(r.degenerate_triangles + r.duplicate_triangles + r.duplicate_vertices, 0);
  // The cracks' walls dip 2.7e-16 in below the floor they stand on: exact predicates see them
  // cross; they only touch.
  EXPECT_TRUE(r.self_intersections_complete);
  EXPECT_EQ(r.self_intersecting_pairs, 0);
  EXPECT_EQ(r.touching_pairs, 1216);
  EXPECT_TRUE(r.usable_for_contact());
  EXPECT_TRUE(r.contact_warnings().empty());
  EXPECT_NEAR(r.box.max.x() - r.box.min.x(), 5.0, 1e-6);
  EXPECT_NEAR(r.box.max.y() - r.box.min.y(), 2.5, 1e-6);
  EXPECT_NEAR(r.box.max.z() - r.box.min.z(), 1.375, 1e-6);
}

TEST(MeshReport, GarmentCodeTorso) {
  const TriangleMesh mesh = read_mesh(test::source_path("molds/garmentcode_mean_female_torso_open.obj"));
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_EQ(r.triangles, 9365);
  EXPECT_EQ(r.vertices, 4805);
  EXPECT_EQ(r.boundary_edges, 249);
  const BoundaryCount independent = count_boundary(mesh);
  ASSERT_TRUE(independent.every_vertex_on_two);
  EXPECT_EQ(r.boundary_loops, independent.loops);
  // Neck, two arm-holes and one loop round the hips where the legs were cut away together.
  EXPECT_EQ(r.boundary_loops, 4);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.non_manifold_edges, 0);
  EXPECT_EQ(r.orientation, MeshOrientation::consistent_open);
  EXPECT_EQ(r.self_intersecting_pairs, 0);
  EXPECT_EQ(r.touching_pairs, 0);
  EXPECT_TRUE(r.usable_for_contact());
}

}  // namespace
}  // namespace fabform::mesh_report_test
