// X3D XML read through its VRML97 translation: the real files of assimp's suite against
// independent counts (ComputerKeyboard's 2020 triangles counted by hand; HelloWorld against the
// Web3D consortium's own X3D-to-VRML97 stylesheet output), X3D's triangle sets, DEF/USE,
// Switch and orientation on handmade files, and bad files refused with their line.
#include "io/x3d_translation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <Eigen/Geometry>

#include "fabform/error.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "support/cli.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::x3d_translation_test {
namespace {

std::string data_file(const std::string& name) { return test::source_path("tests/data/vrml/" + name); }

const char* const kOpen = "<?xml version='1.0' encoding='UTF-8'?>\n<X3D profile='Interchange' version='3.3'>\n<Scene>\n";
const char* const kClose = "</Scene>\n</X3D>\n";

// A unit cube as an IndexedFaceSet, its faces counter-clockwise seen from outside.
const char* const kCube =
    "<Shape><IndexedFaceSet coordIndex='0 3 2 1 -1 4 5 6 7 -1 0 1 5 4 -1 1 2 6 5 -1 2 3 7 6 -1 3 0 4 7 -1'>"
    "<Coordinate point='0 0 0, 1 0 0, 1 1 0, 0 1 0, 0 0 1, 1 0 1, 1 1 1, 0 1 1'/></IndexedFaceSet></Shape>\n";

double signed_volume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (const auto& t : mesh.triangles)
    volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
  return volume;
}

class X3dFiles : public ::testing::Test {
 protected:
  TriangleMesh read(const std::string& body, std::vector<std::string>* warnings = nullptr) {
    return read_mesh(dir.write("body.x3d", kOpen + body + kClose), warnings);
  }
  std::string error_of(const std::string& text) {
    try {
      read_mesh(dir.write("bad.x3d", text));
    } catch (const InputError& error) {
      EXPECT_EQ(error.where().file, dir.path("bad.x3d"));
      return error.what();
    }
    return "no error";
  }
  test::TempDir dir;
};

TEST_F(X3dFiles, ComputerKeyboardHasEveryInstance) {
  std::vector<std::string> warnings;
  const TriangleMesh mesh = read_mesh(data_file("x3d/assimp_ComputerKeyboard.x3d"), &warnings);
  EXPECT_EQ(mesh.triangles.size(), 2020u);  // 100 of them are all assimp 5.2.5 finds
  const bool said = std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
    return w.find("X3D: left out what shapes no surface") != std::string::npos && w.find("TouchSensor") != std::string::npos;
  });
  EXPECT_TRUE(said);
}

// The same scene through the Web3D stylesheet's VRML97 (without the X3D field it kept, which
// VRML97 lacks): the same sphere, point for point.
TEST_F(X3dFiles, HelloWorldIsWhatTheWeb3dTranslationGives) {
  std::string wrl = test::slurp(data_file("assimp_HelloWorld.wrl"));
  const std::string field = "        centerOfRotation 0 -1 0\n";
  ASSERT_NE(wrl.find(field), std::string::npos);
  wrl.erase(wrl.find(field), field.size());
  const TriangleMesh theirs = read_mesh(dir.write("hello.wrl", wrl));
  const TriangleMesh ours = read_mesh(data_file("x3d/assimp_HelloWorld.x3d"));
  ASSERT_EQ(ours.triangles.size(), theirs.triangles.size());
  const auto points = [](const TriangleMesh& m) {
    std::set<std::array<double, 3>> set;
    for (const auto& v : m.vertices) set.insert({v.x(), v.y(), v.z()});
    return set;
  };
  EXPECT_EQ(points(ours), points(theirs));
}

TEST_F(X3dFiles, LinesOnlyIsNoTrianglesAndSaysWhatWasLeftOut) {
  try {
    read_mesh(data_file("x3d/assimp_IndexedLineSet.x3d"));
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("no triangles"), std::string::npos) << error.what();
    EXPECT_NE(error.message().find("IndexedLineSet"), std::string::npos) << error.what();
  }
}

TEST_F(X3dFiles, CubeKeepsItsOutwardFaces) {
  const TriangleMesh cube = read(kCube);
  EXPECT_EQ(cube.triangles.size(), 12u);
  EXPECT_NEAR(signed_volume(cube), 1.0, 1e-12);
  // ccw false declares the other side the front: the reader reverses the triangles so their
  // normals point to the declared front, which here is inside (volume −1).
  std::string inward = kCube;
  inward.insert(inward.find("coordIndex"), "ccw='false' ");
  EXPECT_NEAR(signed_volume(read(inward)), -1.0, 1e-12);
}

TEST_F(X3dFiles, TriangleSetsBecomeFaces) {
  const TriangleMesh indexed = read(
      "<Shape><IndexedTriangleSet index='0 1 2 0 2 3'><Coordinate point='0 0 0 1 0 0 1 1 0 0 1 0'/>"
      "</IndexedTriangleSet></Shape>");
  EXPECT_EQ(indexed.triangles.size(), 2u);
  EXPECT_EQ(indexed.vertices.size(), 4u);
  const TriangleMesh plain = read(
      "<Shape><TriangleSet><Coordinate point='0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1'/></TriangleSet></Shape>");
  EXPECT_EQ(plain.triangles.size(), 2u);
  EXPECT_EQ(plain.vertices.size(), 6u);
}

TEST_F(X3dFiles, DefUseSwitchAndTransformsAreFollowed) {
  const TriangleMesh two = read("<Transform DEF='one-cube'>" + std::string(kCube) + "</Transform>"
                                "<Transform translation='5 0 0'><Transform USE='one-cube'/></Transform>");
  EXPECT_EQ(two.triangles.size(), 24u);
  const auto far = std::max_element(two.vertices.begin(), two.vertices.end(),
                                    [](const auto& a, const auto& b) { return a.x() < b.x(); });
  EXPECT_DOUBLE_EQ(far->x(), 6.0);
  const TriangleMesh chosen = read("<Switch whichChoice='1'><Shape><Box size='1 1 1'/></Shape>" +
                                   std::string(kCube) + "</Switch>");
  EXPECT_NEAR(signed_volume(chosen), 1.0, 1e-12);  // the cube, not the box
  EXPECT_NE(error_of(std::string(kOpen) + "<Switch>" + kCube + "</Switch>" + kClose).find("no triangles"),
            std::string::npos) << "whichChoice -1 (the default) draws nothing";
}

TEST_F(X3dFiles, BadFilesNameTheirLine) {
  EXPECT_NE(error_of(std::string(kOpen) + "<Shape><Box size='1 1'/></Shape>\n" + kClose).find("bad.x3d:4: Box.size: needs 3 numbers, has 2"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kOpen) + "<Transform\n translation='1 nan 0'/>\n" + kClose).find(":4: Transform.translation: 'nan' is not a number"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kOpen) + "<Shape><Cylinder side='yes'/></Shape>\n" + kClose).find("Cylinder.side: must be true or false"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kOpen) + "<Shape><IndexedTriangleSet index='0 1'/></Shape>\n" + kClose).find("2 indices are not whole triangles"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kOpen) + "<Shape>\n<Box></Shape>\n").find("bad.x3d:5: not well-formed XML"), std::string::npos);
  EXPECT_NE(error_of("<svg/>").find("not an X3D file"), std::string::npos);
  EXPECT_NE(error_of("<X3D/>").find("X3D file without a Scene"), std::string::npos);
  EXPECT_NE(error_of("").find("not well-formed XML"), std::string::npos);
}

// The translation names nodes the way VRML97 allows, and writes no node it left out.
TEST(X3dTranslation, IdentifiersAndLeftOutNodes) {
  test::TempDir dir;
  const std::string path = dir.write(
      "t.x3d", std::string(kOpen) + "<Viewpoint/><Transform DEF='1st.part'><Shape><Appearance/><Box/></Shape>"
                                    "</Transform><Transform USE='1st.part'/><TouchSensor DEF='t'/><Group USE='t'/>" + kClose);
  const X3dTranslation t = translate_x3d(path);
  EXPECT_NE(t.vrml.find("DEF _1st_part Transform"), std::string::npos) << t.vrml;
  EXPECT_NE(t.vrml.find("USE _1st_part"), std::string::npos) << t.vrml;
  EXPECT_EQ(t.vrml.find("USE t"), std::string::npos) << "a USE of a node left out is left out";
  EXPECT_EQ(t.left_out.at("Viewpoint"), 1);
  EXPECT_EQ(t.left_out.at("Appearance"), 1);
  EXPECT_EQ(t.left_out.at("TouchSensor"), 1);
  EXPECT_EQ(t.left_out.at("Group"), 1);
}

}  // namespace
}  // namespace fabform::x3d_translation_test
