// Every file in tests/data/meshes through read_mesh, and the shipped mold no other test reads
// (molds/dome_hemisphere_r30mm.obj; the other two molds are read in mesh_reader_test.cpp, every
// file of tests/data/vrml in vrml_reader_test.cpp). A good file gives exactly the triangles
// counted without fabform and assimp, and says in a warning what it dropped; a broken one throws
// InputError whose what() is one line that starts with the file's path and names the problem.
// tests/data/meshes/README.md says where each file comes from and why it is here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "fabform/error.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "test_paths.hpp"

namespace fabform::mesh_corpus_test {
namespace {

namespace fs = std::filesystem;

const std::string kCorpus = "tests/data/meshes/";

// ---- Files that read -------------------------------------------------------------------------

// triangles: counted by tests/data/meshes/count_triangles.py (a reader of its own, standard
// library Python: a polygon of n corners is n - 2 triangles, an STL facet one) and, where the
// comment says so, by hand or from the file's provenance as well.
struct Good {
  const char* file;  // relative to the source tree
  std::size_t triangles;
  const char* warning;  // a piece of the one warning expected, or nullptr for none
};

const Good kGood[] = {
    // 8 vertices, 6 quads (by hand); the last line has no line feed.
    {"assimp_box_without_lineending.obj", 12, nullptr},
    // One LightWave polygon of 66 corners over 64 vertices (by hand: 66 - 2).
    {"assimp_concave_polygon.obj", 64, nullptr},
    // 6 quads (by hand), ASCII, binary, binary with a CR LF after end_header, and binary whose
    // data starts with byte 0x0A (assimp 5.2.5 misreads that one; the reader mends it).
    {"assimp_cube.ply", 12, nullptr},
    {"assimp_cube_binary.ply", 12, nullptr},
    {"assimp_cube_binary_header_with_RN_newline.ply", 12, nullptr},
    {"assimp_cube_binary_starts_with_nl.ply", 12, nullptr},
    // 6 quads 'f' (12 triangles), beside 6 'l' records of 4 corners (3 line segments each) and
    // 6 'p' records of 4 points, which have no surface: 6 × 3 + 6 × 4 = 42 dropped (by hand).
    {"assimp_testmixed.obj", 12, "skipped 42 points, lines and faces of fewer than three corners"},
    // One facet, then an empty solid (by hand).
    {"assimp_triangle_with_empty_solid.stl", 1, "skipped a mesh without faces ('emptySolid')"},
    // SOURCES.md: 47500 triangles; 36972 (18486 quads); 26756.
    {"garmentcode_mean_female.obj", 47500, nullptr},
    {"makehuman_base_hm08.obj", 36972, nullptr},
    {"makehuman_body_only_tri_m.obj", 26756, nullptr},
    // Binary STL whose header starts "solid" and holds bytes that are not UTF-8; 684 bytes =
    // 84 + 50 × 12 (by hand).
    {"numpystl_CubeInvalidUnicode.stl", 12, nullptr},
    {"numpystl_Moon_Chinese.stl", 116, nullptr},
    {"numpystl_StarWithEmptyHeader.stl", 68, nullptr},
    // CAD exports; SOURCES.md gives the same counts.
    {"trimesh_1002_tray_bottom.STL", 4520, nullptr},
    {"trimesh_octagonal_pocket.stl", 3262, nullptr},
    {"trimesh_plate_holes.STL", 1252, nullptr},
    {"trimesh_soup.stl", 100, nullptr},
    // 6 quads with negative (relative) indices.
    {"trimesh_negative_indices.obj", 12, nullptr},
    // "f 1// 2//" (two corners) and one triangle (by hand).
    {"trimesh_notenoughindices.obj", 1, "skipped 1 point, line or face of fewer than three corners"},
    // 6 quads after "OFF8 6 12" (the counts glued to the keyword), by hand.
    {"trimesh_whitespace.off", 12, nullptr},
    // Written by us (make_handmade.py): a unit cube, 12 triangles by construction.
    {"handmade_utf8_bom.obj", 12, nullptr},
    {"handmade_ply_element_before_vertices.ply", 12, nullptr},
    {"handmade_two_corner_face.off", 12, "skipped 1 point, line or face of fewer than three corners"},
    {"handmade_face_without_corners.ply", 12, "skipped 1 point, line or face of fewer than three corners"},
};

// The shipped mold that no other test reads: tools/make_dome_mold.py builds it of 256 meridians,
// each with a pole triangle, 2 × 63 between its 64 rings and a base triangle: 256 × 128 = 32768,
// as count_triangles.py counts it too.
const Good kMolds[] = {
    {"molds/dome_hemisphere_r30mm.obj", 32768, nullptr},
};

std::string path_of(const Good& c) {
  const std::string file = c.file;
  return test::source_path(file.rfind("molds/", 0) == 0 ? file : kCorpus + file);
}

std::string test_name(std::string file) {
  for (char& c : file)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return file;
}

class MeshCorpusGood : public ::testing::TestWithParam<Good> {};

TEST_P(MeshCorpusGood, ReadsEveryTriangle) {
  const Good& expected = GetParam();
  const std::string path = path_of(expected);
  std::vector<std::string> warnings;
  const TriangleMesh mesh = read_mesh(path, &warnings);
  EXPECT_EQ(mesh.triangles.size(), expected.triangles);
  for (const auto& v : mesh.vertices) ASSERT_TRUE(v.allFinite());
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (const int i : t) {
      ASSERT_GE(i, 0);
      ASSERT_LT(i, static_cast<int>(mesh.vertices.size()));
      used[static_cast<std::size_t>(i)] = true;
    }
  // No vertex is left over from what was dropped (points, lines, empty solids).
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
  if (!expected.warning) {
    EXPECT_TRUE(warnings.empty()) << ::testing::PrintToString(warnings);
  } else {
    ASSERT_EQ(warnings.size(), 1u) << ::testing::PrintToString(warnings);
    EXPECT_NE(warnings[0].find(expected.warning), std::string::npos) << warnings[0];
  }
}

INSTANTIATE_TEST_SUITE_P(MeshCorpus, MeshCorpusGood, ::testing::ValuesIn(kGood),
                         [](const auto& case_info) { return test_name(case_info.param.file); });
INSTANTIATE_TEST_SUITE_P(MeshCorpusMolds, MeshCorpusGood, ::testing::ValuesIn(kMolds),
                         [](const auto& case_info) { return test_name(case_info.param.file); });

// ---- Files that do not ---------------------------------------------------------------------

struct Bad {
  const char* file;     // in tests/data/meshes
  int line;             // the line the error names; 0 = none (binary, or the file as a whole)
  const char* problem;  // a piece of the message that names the problem
};

const Bad kBad[] = {
    // Upstream files (README.md has their origin).
    {"assimp_crash-30d6d0f7c529b3b66b4131700b7a4580cd7082df.ply", 0, "PLY header has no end_header line"},
    {"assimp_empty.obj", 0, "the file is empty"},
    {"assimp_empty.ply", 0, "the file is empty"},
    // Declares 3 vertices and 4 faces; 6 lines follow.
    {"assimp_invalid.off", 0, "declares 3 vertices and 4 faces, a line each, but only 6 lines follow"},
    // "f 4 12 2 1" with 8 vertices.
    {"assimp_malformed.obj", 23, "vertex index 12, but the file has 8 vertices"},
    // "v 1e+2 2.e+1 3.1+e2": assimp 5.2.5 would read 3.1.
    {"assimp_number_formats.obj", 11, "'3.1+e2' is not a number"},
    // Only "f 1" and "f 8 7": nothing with a surface.
    {"tinyobj_invalid-face-definition.obj", 0, "no triangles; skipped 2 points, lines and faces of fewer than three"},
    // "f -4 -3 -2" and no vertex at all.
    {"tinyobj_invalid-relative-vertex-index.obj", 1, "relative vertex index -4 reaches before the first vertex"},
    {"tinyobj_issue-140-zero-face-idx.obj", 16, "vertex index 0 (OBJ counts vertices from 1)"},
    {"trimesh_empty.stl", 0, "no triangles; skipped a mesh without faces ('Empty')"},
    // A binary STL of 84 bytes that declares no triangle.
    {"trimesh_stl_empty_bin.stl", 0, "the mesh has no triangles"},
    // Written by us (make_handmade.py), one for each kind of bad input the issue lists.
    {"handmade_truncated_binary.stl", 0, "declares 12 triangles, which take 684 bytes, but the file holds 359 (cut short?)"},
    {"handmade_truncated_binary_solid_header.stl", 0, "starts with 'solid' but holds binary bytes"},
    {"handmade_truncated_ascii.stl", 46, "the file ends inside facet 7 (cut short?)"},
    {"handmade_truncated_binary.ply", 0, "face 11 declares a list of 3 values, more than the data holds"},
    {"handmade_huge_count_binary.stl", 0, "declares 4294967295 triangles"},
    {"handmade_huge_count.ply", 0, "declares 4000000000 vertex elements"},
    {"handmade_huge_count.off", 0, "declares 2000000000 vertices"},
    {"handmade_nan_vertex.obj", 8, "coordinate 'nan' is not finite"},
    {"handmade_inf_vertex_ascii.stl", 20, "coordinate 'inf' is not finite"},
    {"handmade_nan_vertex_binary.stl", 0, "triangle 2 has a coordinate that is not finite"},
    {"handmade_inf_vertex_binary.ply", 0, "vertex 6 has a value that is not finite"},
    {"handmade_index_out_of_range.ply", 30, "a face names vertex 8, but the vertices are 0 to 7"},
    {"handmade_index_out_of_range.off", 22, "a face names vertex 9, but the vertices are 0 to 7"},
    {"handmade_utf16le_bom.obj", 0, "is UTF-16 text"},
    {"handmade_utf16be_bom.stl", 0, "is UTF-16 text"},
    {"handmade_utf16le_no_bom.obj", 1, "holds a NUL byte"},
    {"handmade_empty.stl", 0, "the file is empty"},
    {"handmade_blank_lines.obj", 0, "the file is empty (nothing but white space)"},
};

class MeshCorpusBad : public ::testing::TestWithParam<Bad> {};

TEST_P(MeshCorpusBad, OneLineNamingTheFileAndTheProblem) {
  const Bad& expected = GetParam();
  const std::string path = test::source_path(kCorpus + expected.file);
  ASSERT_TRUE(fs::is_regular_file(path)) << path;
  try {
    const TriangleMesh mesh = read_mesh(path);
    ADD_FAILURE() << "no InputError (" << mesh.triangles.size() << " triangles)";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.find_first_of("\n\r"), std::string::npos) << what;
    EXPECT_EQ(what.rfind(path + (expected.line > 0 ? ":" + std::to_string(expected.line) : std::string()) + ": ", 0), 0u)
        << what;
    EXPECT_EQ(error.where().file, path);
    EXPECT_EQ(error.where().line, expected.line) << what;
    EXPECT_NE(error.message().find(expected.problem), std::string::npos) << what;
    EXPECT_TRUE(std::all_of(what.begin(), what.end(), [](char c) { return c >= 0x20 && c < 0x7F; })) << what;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "not an InputError: " << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(MeshCorpus, MeshCorpusBad, ::testing::ValuesIn(kBad),
                         [](const auto& case_info) { return test_name(case_info.param.file); });

// ---- The tables cover the folder ---------------------------------------------------------------

// A file added to tests/data/meshes without a case above fails here; so does a case whose file
// is gone. README.md, the scripts and LICENSES/ are not meshes.
TEST(MeshCorpus, TablesCoverEveryFile) {
  std::multiset<std::string> listed;
  for (const Good& c : kGood) listed.insert(c.file);
  for (const Bad& c : kBad) listed.insert(c.file);
  std::set<std::string> present;
  for (const auto& entry : fs::directory_iterator(test::source_path(kCorpus))) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() || name == "README.md" || entry.path().extension() == ".py") continue;
    present.insert(name);
    EXPECT_EQ(listed.count(name), 1u) << name << " needs exactly one case in mesh_corpus_test.cpp";
  }
  for (const std::string& name : listed) EXPECT_EQ(present.count(name), 1u) << name << " is not in " << kCorpus;
  EXPECT_EQ(present.size(), std::size(kGood) + std::size(kBad));
}

}  // namespace
}  // namespace fabform::mesh_corpus_test
