// The binary STL reader against assimp (the oracle: the same file read with
// JoinIdenticalVertices gives the same triangles, corner by corner) and on files written here
// whose answers are known: a soup cube merges to 8 vertices, -0 is +0, NaN is refused.
#include "io/binary_stl.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>

#include "fabform/error.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::binary_stl_test {
namespace {

using V = Eigen::Vector3d;

// Writes each triangle with its own three corners, as CAD exporters do.
void write_binary_stl(const std::string& path, const std::vector<std::array<V, 3>>& triangles) {
  std::ofstream out(path, std::ios::binary);
  const char header[80] = {};
  out.write(header, sizeof header);
  const auto count = static_cast<std::uint32_t>(triangles.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  for (const auto& t : triangles) {
    const float normal[3] = {0, 0, 0};
    out.write(reinterpret_cast<const char*>(normal), sizeof normal);
    for (const V& p : t) {
      const float corner[3] = {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
      out.write(reinterpret_cast<const char*>(corner), sizeof corner);
    }
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), sizeof attribute);
  }
}

std::vector<std::array<V, 3>> corners_of(const TriangleMesh& mesh) {
  std::vector<std::array<V, 3>> out;
  for (const auto& t : mesh.triangles)
    out.push_back({mesh.vertices[static_cast<std::size_t>(t[0])], mesh.vertices[static_cast<std::size_t>(t[1])],
                   mesh.vertices[static_cast<std::size_t>(t[2])]});
  return out;
}

TEST(BinaryStl, AgreesWithAssimpCornerByCorner) {
  const std::string path = test::source_path("molds/trimesh_featuretype.STL");
  ASSERT_TRUE(is_binary_stl(path));
  const TriangleMesh mesh = read_binary_stl(path);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_JoinIdenticalVertices);
  ASSERT_NE(scene, nullptr);
  ASSERT_EQ(scene->mNumMeshes, 1u);
  const aiMesh& oracle = *scene->mMeshes[0];
  ASSERT_EQ(mesh.triangles.size(), oracle.mNumFaces);
  EXPECT_EQ(mesh.vertices.size(), 2010u);  // shared/data/SOURCES.md; assimp keeps per-facet normals apart
  for (unsigned f = 0; f < oracle.mNumFaces; ++f)
    for (unsigned c = 0; c < 3; ++c) {
      const aiVector3D& p = oracle.mVertices[oracle.mFaces[f].mIndices[c]];
      // Both hold the file's float32 exactly, so they compare exactly.
      ASSERT_EQ(mesh.vertices[static_cast<std::size_t>(mesh.triangles[f][c])], V(p.x, p.y, p.z))
          << "triangle " << f << " corner " << c;
    }
}

TEST(BinaryStl, SoupCubeMergesToEightVertices) {
  test::TempDir dir;
  const std::string path = dir.path("cube.stl");
  const TriangleMesh cube = test::cube();
  write_binary_stl(path, corners_of(cube));
  ASSERT_TRUE(is_binary_stl(path));
  const TriangleMesh mesh = read_binary_stl(path);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(corners_of(mesh), corners_of(cube));
}

TEST(BinaryStl, NegativeZeroIsZero) {
  test::TempDir dir;
  const std::string path = dir.path("zeros.stl");
  write_binary_stl(path, {{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {V(-0.0, -0.0, -0.0), V(0, 1, 0), V(-1, 0, 0)}});
  EXPECT_EQ(read_binary_stl(path).vertices.size(), 4u);
}

TEST(BinaryStl, NonFiniteCoordinateNamesTheFileAndTriangle) {
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    test::TempDir dir;
    const std::string path = dir.path("bad.stl");
    write_binary_stl(path, {{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {V(0, 0, 0), V(bad, 1, 0), V(-1, 0, 0)}});
    try {
      read_binary_stl(path);
      ADD_FAILURE() << "a non-finite coordinate was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, path);
      EXPECT_NE(e.message().find("triangle 1"), std::string::npos) << e.what();
    }
  }
}

// Bytes after the declared triangles (a trailing byte, a record cut short, a whole record) are
// counted, not read, as common readers do; an ASCII STL is never taken for a binary one, nor a
// binary file shorter than its count says.
TEST(BinaryStl, TrailingBytesAreCountedNotRead) {
  test::TempDir dir;
  const std::string exact = dir.path("cube.stl");
  write_binary_stl(exact, corners_of(test::cube()));
  EXPECT_EQ(binary_stl_trailing_bytes(exact), 0u);
  for (const std::size_t extra : {1, 49, 50, 123}) {
    const std::string path = dir.path("cube_" + std::to_string(extra) + ".stl");
    write_binary_stl(path, corners_of(test::cube()));
    std::ofstream(path, std::ios::binary | std::ios::app) << std::string(extra, 'x');
    EXPECT_EQ(binary_stl_trailing_bytes(path), extra);
    EXPECT_TRUE(is_binary_stl(path));
    const TriangleMesh mesh = read_binary_stl(path);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_EQ(mesh.vertices.size(), 8u);
  }
  // SolidWorks starts a binary header with "solid": its count and floats hold NUL bytes.
  std::string solid_header = "solid part";
  solid_header.resize(80, ' ');
  const std::string named = dir.path("named.stl");
  write_binary_stl(named, corners_of(test::cube()));
  {
    std::fstream file(named, std::ios::binary | std::ios::in | std::ios::out);
    file.write(solid_header.data(), 80);
  }
  std::ofstream(named, std::ios::binary | std::ios::app) << '\n';
  EXPECT_EQ(binary_stl_trailing_bytes(named), 1u);
  const std::string ascii = "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid x\n";
  EXPECT_FALSE(binary_stl_trailing_bytes(dir.write("ascii.stl", ascii)));
  EXPECT_FALSE(is_binary_stl(dir.write("short_ascii.stl", "solid x\nendsolid x\n")));
  const std::string cut = dir.path("cut.stl");
  write_binary_stl(cut, corners_of(test::cube()));
  std::filesystem::resize_file(cut, 84 + 50 * 12 - 1);
  EXPECT_FALSE(is_binary_stl(cut));
  EXPECT_FALSE(is_binary_stl(dir.path("missing.stl")));
}

}  // namespace
}  // namespace fabform::binary_stl_test
