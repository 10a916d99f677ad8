// `fabform check MESH [--units U] [--repair OUT.obj]` on the real binary: the report of a real
// CAD part, a refusal of an inverted body in one line, a repair that makes it usable, and
// usage errors that write nothing.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "fabform/io/obj_text.hpp"
#include "support/cli.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::check_command_test {
namespace {

using test::line_count;
using test::Outcome;
using test::run_fabform;

class CheckCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    TriangleMesh inverted = test::cube({0, 0, 0}, 10.0);
    for (auto& t : inverted.triangles) test::flip(&t);
    dir.write("inverted.obj", obj_text(inverted));
    std::filesystem::create_directories(dir.path("folder.stl"));
  }
  bool exists(const std::string& name) const { return std::filesystem::exists(dir.path(name)); }
  test::TempDir dir;
};

TEST_F(CheckCommand, ReportsTheShippedMoldInMetres) {
  const Outcome o = run_fabform(dir, "check '" + test::source_path("molds/trimesh_featuretype.STL") + "' --units in");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err, "");
  for (const char* line : {"triangles           3476", "vertices            2010", "size (m)            0.127 x 0.0635 x 0.034925",
                           "open:", "verdict: usable for contact"})
    EXPECT_NE(o.out.find(line), std::string::npos) << line << " missing from\n" << o.out;
}

TEST_F(CheckCommand, InvertedBodyIsRefusedInOneLine) {
  const Outcome o = run_fabform(dir, "check inverted.obj --units mm");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(test::error_line_count(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("inverted.obj: the faces point inward"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("--repair"), std::string::npos) << o.err;
  EXPECT_NE(o.out.find("enclosed volume     -1e-06 m^3"), std::string::npos) << o.out;
}

TEST_F(CheckCommand, RepairWritesAUsableMeshAndSaysWhatChanged) {
  const Outcome o = run_fabform(dir, "check inverted.obj --units mm --repair fixed.obj");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("12 triangles flipped"), std::string::npos) << o.out;
  ASSERT_TRUE(exists("fixed.obj"));
  const Outcome again = run_fabform(dir, "check fixed.obj --units mm");
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find("consistent, outward"), std::string::npos) << again.out;
  EXPECT_NE(again.out.find("enclosed volume     1e-06 m^3"), std::string::npos) << again.out;
}

// A reader's warnings are part of the report: a binary STL with a byte after its triangles.
TEST_F(CheckCommand, ReaderWarningsAreReported) {
  std::string stl(84 + 50, '\0');
  stl[80] = 1;  // one triangle
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::memcpy(&stl[84 + 12], corners, sizeof corners);
  dir.write("trailing.stl", stl + "\n");
  const Outcome o = run_fabform(dir, "check trailing.stl");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("  warning: ignored 1 byte after the 1 triangle the binary STL declares\n"), std::string::npos) << o.out;
}

// What --repair promised is what the written file is, on a mesh whose repair has work to do:
// a soup of the cube, one triangle flipped and one doubled, far from the origin at 17 digits.
TEST_F(CheckCommand, TheRepairedFileReportsWhatTheRepairPromised) {
  TriangleMesh mesh = test::soup(test::cube({1234.5678901234567, -0.1, 7.25}, 0.3));
  test::flip(&mesh.triangles[3]);
  mesh.triangles.push_back(mesh.triangles[5]);
  dir.write("messy.obj", obj_text(mesh));
  const Outcome o = run_fabform(dir, "check messy.obj --repair fixed.obj");
  ASSERT_EQ(o.status, 0) << o.err;
  const std::string promised = o.out.substr(o.out.find("after repair:\n") + 14);
  const Outcome again = run_fabform(dir, "check fixed.obj");
  ASSERT_EQ(again.status, 0) << again.err;
  const std::size_t from = again.out.find("  vertices"), to = again.out.find("verdict:");
  EXPECT_EQ(promised.substr(0, promised.find("written:")), again.out.substr(from, to - from));
}

struct BadCheck {
  const char* name;
  const char* arguments;
  const char* expected_in_message;
};

class CheckCommandBadInput : public CheckCommand, public ::testing::WithParamInterface<BadCheck> {};

TEST_P(CheckCommandBadInput, ExitsTwoWithOneLineAndWritesNothing) {
  const Outcome o = run_fabform(dir, GetParam().arguments);
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_EQ(test::error_line_count(o.err), 1) << o.err;
  EXPECT_NE(o.err.find(GetParam().expected_in_message), std::string::npos) << o.err;
  EXPECT_FALSE(exists("out.obj"));
}

INSTANTIATE_TEST_SUITE_P(
    Usage, CheckCommandBadInput,
    ::testing::Values(BadCheck{"MissingMesh", "check nowhere.stl --repair out.obj", "nowhere.stl: no such mesh file"},
                      BadCheck{"Folder", "check folder.stl --repair out.obj", "folder.stl: is a folder, not a mesh file"},
                      BadCheck{"NoMesh", "check", "MESH"},
                      BadCheck{"UnknownUnit", "check inverted.obj --units furlong --repair out.obj", "furlong"},
                      BadCheck{"RepairNotObj", "check inverted.obj --repair out.stl", "OBJ"},
                      BadCheck{"TwoMeshes", "check inverted.obj inverted.obj", "one mesh"},
                      BadCheck{"UnknownOption", "check inverted.obj --fix", "--fix: unknown option"}),
    [](const auto& case_info) { return std::string(case_info.param.name); });

}  // namespace
}  // namespace fabform::check_command_test
