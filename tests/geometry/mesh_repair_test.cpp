// repair_mesh: what it changes, counted, and that what comes out inspects clean: a soup is
// merged into a closed cube, flipped and duplicated triangles are fixed, degenerate ones go,
// a clean mesh is left as it is (the shipped molds among them).
#include "fabform/geometry/mesh_repair.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "fabform/geometry/mesh_report.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "support/shapes.hpp"
#include "test_paths.hpp"

namespace fabform::mesh_repair_test {
namespace {

using test::cube;
using test::cycles;
using test::flip;
using test::soup;
using V = Eigen::Vector3d;

// What a repaired closed cube must be: 8 vertices, 12 triangles, closed, outward, clean.
void expect_clean_cube(const TriangleMesh& mesh) {
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_EQ(r.vertices, 8);
  EXPECT_EQ(r.triangles, 12);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.orientation, MeshOrientation::outward);
  EXPECT_NEAR(r.signed_volume, 1.0, 1e-15);
  EXPECT_EQ(r.degenerate_triangles + r.duplicate_triangles + r.duplicate_vertices + r.isolated_vertices +
                r.non_manifold_edges + r.inconsistent_edges,
            0);
  EXPECT_TRUE(r.usable_for_contact());
}

TEST(MeshRepair, CleanCubeIsLeftAsItIs) {
  const RepairResult r = repair_mesh(cube());
  EXPECT_FALSE(r.changed());
  EXPECT_TRUE(r.changes().empty());
  expect_clean_cube(r.mesh);
  EXPECT_EQ(r.mesh.vertices, cube().vertices) << "coordinates are not moved";
}

TEST(MeshRepair, SoupIsMergedIntoAClosedCube) {
  const RepairResult r = repair_mesh(soup(cube()));
  EXPECT_EQ(r.merged_vertices, 28);
  EXPECT_EQ(r.reversed_triangles, 0);
  expect_clean_cube(r.mesh);
  ASSERT_EQ(r.changes().size(), 1u);
  EXPECT_NE(r.changes()[0].find("28 duplicate vertices merged"), std::string::npos) << r.changes()[0];
}

TEST(MeshRepair, FlippedCubeIsTurnedOutward) {
  TriangleMesh mesh = cube();
  for (auto& t : mesh.triangles) flip(&t);
  const RepairResult r = repair_mesh(mesh);
  EXPECT_EQ(r.reversed_triangles, 12);
  expect_clean_cube(r.mesh);
}

TEST(MeshRepair, OneFlippedTriangleIsFlippedBack) {
  for (int which : {0, 5, 11}) {  // the first triangle too, where the soup orientation starts
    TriangleMesh mesh = cube();
    flip(&mesh.triangles[static_cast<std::size_t>(which)]);
    const RepairResult r = repair_mesh(mesh);
    EXPECT_EQ(r.reversed_triangles, 1) << "triangle " << which;
    expect_clean_cube(r.mesh);
  }
}

TEST(MeshRepair, DegenerateAndDuplicateTrianglesAreDropped) {
  TriangleMesh mesh = cube();
  mesh.vertices.push_back({0.5, 0.0, 0.0});                 // middle of edge 0–1
  mesh.triangles.push_back({0, 8, 1});                      // zero area, distinct vertices
  mesh.triangles.push_back({0, 0, 1});                      // repeated vertex
  mesh.triangles.push_back({0, 3, 2});                      // triangle 0 again, reversed
  mesh.triangles.push_back(mesh.triangles[1]);              // triangle 1 again
  const RepairResult r = repair_mesh(mesh);
  EXPECT_EQ(r.removed_degenerate, 2);
  EXPECT_EQ(r.removed_duplicate, 2);
  EXPECT_EQ(r.removed_isolated_vertices, 1);  // the midpoint, used only by the dropped triangle
  expect_clean_cube(r.mesh);
  EXPECT_EQ(r.changes().size(), 3u);
}

TEST(MeshRepair, OpenMeshKeepsTheOrientationMostOfItHadAndStaysOpen) {
  for (int which : {0, 7}) {
    TriangleMesh mesh = cube();
    mesh.triangles.erase(mesh.triangles.begin() + 2, mesh.triangles.begin() + 4);  // no top
    flip(&mesh.triangles[static_cast<std::size_t>(which)]);
    const RepairResult r = repair_mesh(mesh);
    EXPECT_EQ(r.reversed_triangles, 1) << "triangle " << which;
    TriangleMesh expected = cube();
    expected.triangles.erase(expected.triangles.begin() + 2, expected.triangles.begin() + 4);
    EXPECT_EQ(cycles(r.mesh), cycles(expected)) << "triangle " << which;
    const MeshReport after = inspect_mesh(r.mesh);
    EXPECT_EQ(after.orientation, MeshOrientation::consistent_open);
    EXPECT_EQ(after.boundary_loops, 1);
  }
}

TEST(MeshRepair, NothingLeftIsAnEmptyMesh) {
  TriangleMesh mesh;
  mesh.vertices = {V(0, 0, 0), V(1, 0, 0), V(2, 0, 0)};
  mesh.triangles = {{0, 1, 2}};
  const RepairResult r = repair_mesh(mesh);
  EXPECT_EQ(r.removed_degenerate, 1);
  EXPECT_TRUE(r.mesh.triangles.empty());
  EXPECT_FALSE(inspect_mesh(r.mesh).usable_for_contact());
}

TEST(MeshRepair, InvertedSecondCubeIsTurnedOutward) {
  TriangleMesh mesh = cube();
  const TriangleMesh second = cube(V(3, 0, 0));
  for (const auto& v : second.vertices) mesh.vertices.push_back(v);
  for (auto t : second.triangles) {
    flip(&t);
    mesh.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  }
  const RepairResult r = repair_mesh(mesh);
  EXPECT_EQ(r.reversed_triangles, 12);
  const MeshReport after = inspect_mesh(r.mesh);
  EXPECT_EQ(after.orientation, MeshOrientation::outward);
  EXPECT_NEAR(after.signed_volume, 2.0, 1e-14);
}

TEST(MeshRepair, BadIndexIsRejected) {
  TriangleMesh mesh = cube();
  mesh.triangles.push_back({0, 1, 99});
  EXPECT_THROW(repair_mesh(mesh), std::invalid_argument);
}

TEST(MeshRepair, ShippedMoldsNeedNothing) {
  for (const char* name : {"molds/trimesh_featuretype.STL", "molds/garmentcode_mean_female_torso_open.obj"}) {
    const TriangleMesh mesh = read_mesh(test::source_path(name));
    const RepairResult r = repair_mesh(mesh);
    EXPECT_FALSE(r.changed()) << name << ": " << (r.changes().empty() ? "" : r.changes()[0]);
    EXPECT_EQ(r.mesh.triangles.size(), mesh.triangles.size()) << name;
    const MeshReport before = inspect_mesh(mesh), after = inspect_mesh(r.mesh);
    EXPECT_EQ(after.boundary_edges, before.boundary_edges) << name;
    EXPECT_NEAR(after.signed_volume, before.signed_volume, 1e-9 * std::abs(before.signed_volume)) << name;
  }
}

}  // namespace
}  // namespace fabform::mesh_repair_test
