// read_mesh on the shipped molds (counts checked independently of assimp) and on small
// malformed files written to a temporary directory.
#include "fabform/io/mesh_reader.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cctype>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>

#include "fabform/error.hpp"
#include "test_paths.hpp"

namespace fabform::mesh_reader_test {
namespace {

namespace fs = std::filesystem;

const std::string kStl = "molds/trimesh_featuretype.STL";
const std::string kObj = "molds/garmentcode_mean_female_torso_open.obj";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expect_well_formed(const TriangleMesh& mesh) {
  for (const auto& v : mesh.vertices) ASSERT_TRUE(v.allFinite());
  for (const auto& t : mesh.triangles)
    for (const int i : t) {
      ASSERT_GE(i, 0);
      ASSERT_LT(i, static_cast<int>(mesh.vertices.size()));
    }
}

TEST(MeshReader, FeaturetypeStl) {
  const std::string path = test::source_path(kStl);
  const TriangleMesh mesh = read_mesh(path);
  expect_well_formed(mesh);
  // /work/shared/data/SOURCES.md: 3476 triangles, 2010 unique vertices.
  EXPECT_EQ(mesh.triangles.size(), 3476u);
  EXPECT_EQ(mesh.vertices.size(), 2010u);  // identical positions are joined
  // Independently: a binary STL is an 80-byte header, a uint32 triangle count (little
  // endian), then 50 bytes per triangle.
  const std::string bytes = slurp(path);
  ASSERT_GE(bytes.size(), 84u);
  std::uint32_t count = 0;
  for (int k = 3; k >= 0; --k)
    count = (count << 8) | static_cast<std::uint8_t>(bytes[static_cast<std::size_t>(80 + k)]);
  EXPECT_EQ(count, 3476u);
  EXPECT_EQ(bytes.size(), 84u + 50u * count);
  // 5.0 × 2.5 × 1.375 (inches, per SOURCES.md), centred in x and y, from z = 0.
  // Tolerance: the file stores floats.
  const BoundingBox box = bounding_box(mesh.vertices);
  EXPECT_NEAR(box.max.x() - box.min.x(), 5.0, 1e-6);
  EXPECT_NEAR(box.max.y() - box.min.y(), 2.5, 1e-6);
  EXPECT_NEAR(box.max.z() - box.min.z(), 1.375, 1e-6);
}

TEST(MeshReader, TorsoObj) {
  const std::string path = test::source_path(kObj);
  const TriangleMesh mesh = read_mesh(path);
  expect_well_formed(mesh);
  // SOURCES.md: 4805 vertices, 9365 triangles. Independently: count the 'v' and 'f' lines
  // (every face of this file is a triangle: each 'f' line has three corners).
  std::ifstream in(path);
  std::string line;
  std::size_t v_lines = 0, f_lines = 0, triangle_corners = 0;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) == 0) ++v_lines;
    if (line.rfind("f ", 0) == 0) {
      ++f_lines;
      std::istringstream corners(line.substr(2));
      std::string corner;
      std::size_t n = 0;
      while (corners >> corner) ++n;
      triangle_corners += n == 3;
    }
  }
  EXPECT_EQ(f_lines, 9365u);
  EXPECT_EQ(triangle_corners, f_lines);
  EXPECT_EQ(mesh.triangles.size(), f_lines);
  EXPECT_EQ(v_lines, 4805u);
  EXPECT_EQ(mesh.vertices.size(), v_lines);
  // SOURCES.md, to its 3 decimals: y 0.854..1.400, x ±0.182, z −0.140..0.143 (metres).
  const BoundingBox box = bounding_box(mesh.vertices);
  EXPECT_NEAR(box.min.y(), 0.854, 1e-3);
  EXPECT_NEAR(box.max.y(), 1.400, 1e-3);
  EXPECT_NEAR(box.min.x(), -0.182, 1e-3);
  EXPECT_NEAR(box.max.x(), 0.182, 1e-3);
  EXPECT_NEAR(box.min.z(), -0.140, 1e-3);
  EXPECT_NEAR(box.max.z(), 0.143, 1e-3);
}

class MeshReaderFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fabform_mesh_reader_test_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream out(path, std::ios::binary);
    out << text;
    return path;
  }
  // read_mesh must throw InputError naming the file.
  void expect_input_error(const std::string& path) {
    try {
      const TriangleMesh mesh = read_mesh(path);
      ADD_FAILURE() << "no InputError for " << path << " (" << mesh.triangles.size() << " triangles)";
    } catch (const InputError& error) {
      EXPECT_EQ(error.where().file, path);
      EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    } catch (const std::exception& error) {
      ADD_FAILURE() << "not an InputError: " << error.what();
    }
  }
  fs::path dir_;
};

TEST_F(MeshReaderFiles, ObjQuadIsTriangulated) {
  const std::string path = write("quad.obj", "v 0 0 0\nv 2 0 0\nv 2 3 0\nv 0 3 0\nf 1 2 3 4\n");
  const TriangleMesh mesh = read_mesh(path);
  expect_well_formed(mesh);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  // The two triangles tile the 2 × 3 quad, both facing +z like the quad.
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d n = (mesh.vertices[static_cast<std::size_t>(t[1])] - mesh.vertices[static_cast<std::size_t>(t[0])])
                                  .cross(mesh.vertices[static_cast<std::size_t>(t[2])] - mesh.vertices[static_cast<std::size_t>(t[0])]);
    EXPECT_GT(n.z(), 0.0);
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 6.0, 1e-12);
}

TEST_F(MeshReaderFiles, AsciiStlSharedVerticesAreJoined) {
  const std::string path = write("two.stl",
                                 "solid two\r\n"
                                 "facet normal 0 0 1\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 0 0\r\n"
                                 "vertex 0 1 0\r\nendloop\r\nendfacet\r\n"
                                 "facet normal 0 0 1\r\nouter loop\r\nvertex 1 0 0\r\nvertex 1 1 0\r\n"
                                 "vertex 0 1 0\r\nendloop\r\nendfacet\r\n"
                                 "endsolid two\r\n");
  const TriangleMesh mesh = read_mesh(path);
  expect_well_formed(mesh);
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 4u);
}

TEST_F(MeshReaderFiles, MissingFile) { expect_input_error((dir_ / "nothing_here.obj").string()); }

TEST_F(MeshReaderFiles, DirectoryIsNotAMesh) {
  fs::create_directories(dir_ / "folder.obj");
  const std::string path = (dir_ / "folder.obj").string();
  expect_input_error(path);
  try {
    read_mesh(path);
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), path + ": is a folder, not a mesh file");
  }
}

// OBJ is read in double: 17 significant digits (what fabform check --repair writes) come back
// bit for bit, where assimp's float would move them and merge neighbours.
TEST_F(MeshReaderFiles, ObjCoordinatesAreReadExactly) {
  const Eigen::Vector3d a(1234.5678901234567, -0.036491513252258301, 1e-300), b(1234.5678901234568, 0.1, 0.3),
      c(0.12345678901234567, 123456.78901234567, -7.5);
  char text[400];
  std::snprintf(text, sizeof text, "v %.17g %.17g %.17g\nv %.17g %.17g %.17g\nv %.17g %.17g %.17g\nf 1 2 3\n", a.x(), a.y(),
                a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z());
  const TriangleMesh mesh = read_mesh(write("exact.obj", text));
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0], a);
  EXPECT_EQ(mesh.vertices[1], b);  // one double step from a's x: apart, not merged
  EXPECT_EQ(mesh.vertices[2], c);
}

// An L-shaped hexagon listed from the corner next to its reflex one, as Rhino writes n-gons,
// with texture and normal indices: its triangles cover the L (area 3), not its hull.
TEST_F(MeshReaderFiles, ObjConcaveFaceIsTriangulatedInsideIt) {
  const std::string path = write("l.obj",
                                 "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nvt 0 0\nvn 0 0 1\n"
                                 "f 3/1/1 4/1/1 5/1/1 6/1/1 1/1/1 2/1/1\n");
  const TriangleMesh mesh = read_mesh(path);
  ASSERT_EQ(mesh.triangles.size(), 4u);
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d n = (mesh.vertices[static_cast<std::size_t>(t[1])] - mesh.vertices[static_cast<std::size_t>(t[0])])
                                  .cross(mesh.vertices[static_cast<std::size_t>(t[2])] - mesh.vertices[static_cast<std::size_t>(t[0])]);
    EXPECT_GT(n.z(), 0.0);
    area += 0.5 * n.z();
  }
  EXPECT_DOUBLE_EQ(area, 3.0);
}

// A face may name vertices listed after it (positive indices), or count back from the last
// vertex read so far (negative ones), as assimp and most readers allow.
TEST_F(MeshReaderFiles, ObjIndicesReachForwardAndBack) {
  const TriangleMesh mesh = read_mesh(write("order.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -1 -2\nv 5 5 5\n"));
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 3u) << "the fifth-line vertex is used by no face";
  EXPECT_EQ(mesh.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{0, 2, 1}));
}

TEST_F(MeshReaderFiles, BinaryStlTrailingBytesAreAWarning) {
  std::string stl(84 + 50, '\0');
  stl[80] = 1;  // one triangle
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::memcpy(&stl[84 + 12], corners, sizeof corners);
  std::vector<std::string> warnings;
  const TriangleMesh mesh = read_mesh(write("one.stl", stl + "x"), &warnings);
  EXPECT_EQ(mesh.triangles.size(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "ignored 1 byte after the 1 triangle the binary STL declares");
}

TEST_F(MeshReaderFiles, EmptyFiles) {
  expect_input_error(write("empty.obj", ""));
  expect_input_error(write("empty.stl", ""));
}

TEST_F(MeshReaderFiles, NoTriangles) {
  expect_input_error(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"));
  expect_input_error(write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n"));
  expect_input_error(write("comments.obj", "# nothing but a comment\n"));
  expect_input_error(write("empty_solid.stl", "solid nothing\nendsolid nothing\n"));
}

TEST_F(MeshReaderFiles, Garbage) {
  std::string bytes(300, '\0');
  for (std::size_t k = 0; k < bytes.size(); ++k) bytes[k] = static_cast<char>((k * 37 + 11) % 251);
  expect_input_error(write("garbage.stl", bytes.substr(0, 60)));  // shorter than a binary header
  expect_input_error(write("garbage.obj", bytes));
  expect_input_error(write("garbage.xyzzy", bytes));
}

// Real files of each format from mature loaders' test suites (tests/data/meshes/README.md);
// the counts were taken by hand from the files.
struct FormatCase {
  const char* file;
  std::size_t triangles;
};

class MeshReaderFormat : public ::testing::TestWithParam<FormatCase> {};

TEST_P(MeshReaderFormat, ReadsEveryTriangle) {
  const TriangleMesh mesh = read_mesh(test::source_path(std::string("tests/data/meshes/") + GetParam().file));
  EXPECT_EQ(mesh.triangles.size(), GetParam().triangles);
  for (const auto& t : mesh.triangles)
    for (const int v : t) EXPECT_LT(static_cast<std::size_t>(v), mesh.vertices.size());
}

INSTANTIATE_TEST_SUITE_P(Formats, MeshReaderFormat,
                         ::testing::Values(FormatCase{"assimp_cube.ply", 12},
                                           FormatCase{"assimp_cube_binary.ply", 12},
                                           FormatCase{"numpystl_Moon_Chinese.stl", 116},
                                           FormatCase{"numpystl_StarWithEmptyHeader.stl", 68}),
                         [](const auto& case_info) {
                           std::string name = case_info.param.file;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace fabform::mesh_reader_test
