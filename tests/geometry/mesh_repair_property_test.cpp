// repair_mesh never harms, on every mesh the repository holds (molds/, tests/data/meshes,
// tests/data/vrml) and on those of ../shared/data when it is there (a clone without it skips
// them): the repaired triangles are input triangles, position for position, and every input
// triangle is kept unless the report counts it removed (so the surface is the input's: the
// Hausdorff distance is 0, checked by sampling against brute-force closest points on the
// smaller meshes, within 1e-9 of the size); the bounding box of what is kept is the input's;
// repairing again changes nothing; and the OBJ `fabform check --repair` writes reads back as a
// mesh whose report is the repaired mesh's, field for field.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "fabform/error.hpp"
#include "fabform/geometry/closest_point.hpp"
#include "fabform/geometry/mesh_repair.hpp"
#include "fabform/geometry/mesh_report.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "fabform/io/obj_text.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::mesh_repair_property_test {
namespace {

namespace fs = std::filesystem;
using Position = std::array<double, 3>;
using PositionTriangle = std::array<Position, 3>;  // sorted: a triangle whichever way it runs

const char* const kFolders[] = {"molds", "tests/data/meshes", "tests/data/vrml", "tests/data/vrml/x3d",
                                "../shared/data/mold", "../shared/data/torso", "../shared/data/vrml",
                                "../shared/data/vrml/x3d", "../shared/data/malformed/obj",
                                "../shared/data/malformed/off", "../shared/data/malformed/ply",
                                "../shared/data/malformed/stl"};

// Every file that reads as a mesh, by path; files that are refused are other tests' business.
std::map<std::string, TriangleMesh> corpus() {
  std::map<std::string, TriangleMesh> meshes;
  for (const char* folder : kFolders) {
    const fs::path dir = test::source_path(folder);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      try {
        meshes.emplace(fs::canonical(entry.path()).string(), read_mesh(entry.path().string()));
      } catch (const InputError&) {
      }
    }
  }
  return meshes;
}

const std::map<std::string, TriangleMesh>& meshes() {
  static const std::map<std::string, TriangleMesh> all = corpus();
  return all;
}

Position position(const TriangleMesh& mesh, int v) {
  const auto& p = mesh.vertices[static_cast<std::size_t>(v)];
  return {p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
}

std::multiset<PositionTriangle> triangles_by_position(const TriangleMesh& mesh) {
  std::multiset<PositionTriangle> out;
  for (const auto& t : mesh.triangles) {
    PositionTriangle p{position(mesh, t[0]), position(mesh, t[1]), position(mesh, t[2])};
    std::sort(p.begin(), p.end());
    out.insert(p);
  }
  return out;
}

BoundingBox used_box(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> used;
  for (const auto& t : mesh.triangles)
    for (const int v : t) used.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
  return bounding_box(used);
}

// The distance from a point to the nearest of the triangles, by trying them all.
double distance_to(const Eigen::Vector3d& p, const TriangleMesh& mesh) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles) {
    const auto& v = mesh.vertices;
    const Eigen::Vector3d q = closest_point_on_triangle(p, v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                                                        v[static_cast<std::size_t>(t[2])]).point;
    best = std::min(best, (p - q).norm());
  }
  return best;
}

// The one-sided Hausdorff distance from `from`'s triangles to `to`, sampled at 7 points of each.
double sampled_distance(const TriangleMesh& from, const TriangleMesh& to) {
  double worst = 0.0;
  const Eigen::Vector3d weights[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1 / 3.0, 1 / 3.0, 1 / 3.0}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.7, 0.1, 0.2}};
  for (const auto& t : from.triangles)
    for (const auto& w : weights) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (int c = 0; c < 3; ++c) p += w[c] * from.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(c)])];
      worst = std::max(worst, distance_to(p, to));
    }
  return worst;
}

void expect_same_report(const MeshReport& a, const MeshReport& b, const std::string& name) {
  EXPECT_EQ(a.vertices, b.vertices) << name;
  EXPECT_EQ(a.triangles, b.triangles) << name;
  EXPECT_EQ(a.box.min, b.box.min) << name;
  EXPECT_EQ(a.box.max, b.box.max) << name;
  EXPECT_EQ(a.isolated_vertices, b.isolated_vertices) << name;
  EXPECT_EQ(a.duplicate_vertices, b.duplicate_vertices) << name;
  EXPECT_EQ(a.degenerate_triangles, b.degenerate_triangles) << name;
  EXPECT_EQ(a.duplicate_triangles, b.duplicate_triangles) << name;
  EXPECT_EQ(a.edges, b.edges) << name;
  EXPECT_EQ(a.boundary_edges, b.boundary_edges) << name;
  EXPECT_EQ(a.boundary_loops, b.boundary_loops) << name;
  EXPECT_EQ(a.non_manifold_edges, b.non_manifold_edges) << name;
  EXPECT_EQ(a.closed, b.closed) << name;
  EXPECT_EQ(a.components, b.components) << name;
  EXPECT_EQ(a.inconsistent_edges, b.inconsistent_edges) << name;
  EXPECT_EQ(a.orientation, b.orientation) << name;
  EXPECT_DOUBLE_EQ(a.signed_volume, b.signed_volume) << name;
  EXPECT_EQ(a.self_intersecting_pairs, b.self_intersecting_pairs) << name;
  EXPECT_EQ(a.touching_pairs, b.touching_pairs) << name;
}

TEST(MeshRepairProperties, TheCorpusIsThere) {
  // molds/ (5 files, two of them not meshes) and tests/data hold 40 files that read without
  // ../shared/data; fewer means the reader refuses what it read before.
  std::size_t in_repository = 0;
  for (const auto& [path, mesh] : meshes()) in_repository += path.find("/shared/data/") == std::string::npos;
  EXPECT_GE(in_repository, 30u);
  std::printf("repair properties over %zu meshes (%zu from ../shared/data)\n", meshes().size(), meshes().size() - in_repository);
}

TEST(MeshRepairProperties, KeepsTheSurfaceAndTheBoundingBox) {
  for (const auto& [name, mesh] : meshes()) {
    const RepairResult r = repair_mesh(mesh);
    const auto before = triangles_by_position(mesh);
    const auto after = triangles_by_position(r.mesh);
    EXPECT_TRUE(std::includes(before.begin(), before.end(), after.begin(), after.end()))
        << name << ": a repaired triangle is not one of the input's";
    EXPECT_EQ(before.size() - after.size(), static_cast<std::size_t>(r.removed_degenerate + r.removed_duplicate))
        << name << ": triangles went that the report does not count";
    if (r.removed_degenerate + r.removed_duplicate == 0) {
      EXPECT_EQ(used_box(r.mesh).min, used_box(mesh).min) << name;
      EXPECT_EQ(used_box(r.mesh).max, used_box(mesh).max) << name;
    }
    if (mesh.triangles.size() > 3000) continue;  // brute force: triangles squared
    const double tolerance = 1e-9 * used_box(mesh).diagonal();
    EXPECT_LE(sampled_distance(r.mesh, mesh), tolerance) << name;
    if (r.removed_degenerate + r.removed_duplicate == 0) {
      EXPECT_LE(sampled_distance(mesh, r.mesh), tolerance) << name;
    }
  }
}

TEST(MeshRepairProperties, RepairingTwiceIsRepairingOnce) {
  for (const auto& [name, mesh] : meshes()) {
    const RepairResult once = repair_mesh(mesh);
    const RepairResult twice = repair_mesh(once.mesh);
    EXPECT_FALSE(twice.changed()) << name << ": " << (twice.changes().empty() ? "" : twice.changes()[0]);
    EXPECT_EQ(twice.mesh.vertices, once.mesh.vertices) << name;
    EXPECT_EQ(test::cycles(twice.mesh), test::cycles(once.mesh)) << name;
  }
}

TEST(MeshRepairProperties, TheWrittenFileIsWhatTheReportPromised) {
  const test::TempDir dir;
  for (const auto& [name, mesh] : meshes()) {
    const RepairResult r = repair_mesh(mesh);
    const std::string written = dir.write("repaired.obj", obj_text(r.mesh, "repaired"));
    const TriangleMesh back = read_mesh(written);
    expect_same_report(inspect_mesh(back), inspect_mesh(r.mesh), name);
    EXPECT_EQ(triangles_by_position(back), triangles_by_position(r.mesh)) << name << ": the file moved a vertex";
  }
}

}  // namespace
}  // namespace fabform::mesh_repair_property_test
