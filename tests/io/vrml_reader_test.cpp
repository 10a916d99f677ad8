// read_vrml on real VRML97 exports (tests/data/vrml; the expected counts and boxes were taken
// without Coin, see tests/data/vrml/README.md) and on small files written to a temporary
// directory, whose counts follow from the text of each file.
#include "io/vrml_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "fabform/error.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "test_paths.hpp"

namespace fabform::vrml_reader_test {
namespace {

namespace fs = std::filesystem;

std::string data_file(const std::string& name) { return test::source_path("tests/data/vrml/" + name); }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Eigen::Vector3d corner(const TriangleMesh& mesh, const std::array<int, 3>& t, int k) {
  return mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
}

// Twice the triangle's area along its right-hand normal.
Eigen::Vector3d area_normal(const TriangleMesh& mesh, const std::array<int, 3>& t) {
  return (corner(mesh, t, 1) - corner(mesh, t, 0)).cross(corner(mesh, t, 2) - corner(mesh, t, 0));
}

// Volume enclosed by a closed mesh: positive when its normals point outward.
double signed_volume(const TriangleMesh& mesh) {
  double six_v = 0.0;
  for (const auto& t : mesh.triangles) six_v += corner(mesh, t, 0).dot(corner(mesh, t, 1).cross(corner(mesh, t, 2)));
  return six_v / 6.0;
}

void expect_well_formed(const TriangleMesh& mesh) {
  for (const auto& v : mesh.vertices) ASSERT_TRUE(v.allFinite());
  for (const auto& t : mesh.triangles)
    for (const int i : t) {
      ASSERT_GE(i, 0);
      ASSERT_LT(i, static_cast<int>(mesh.vertices.size()));
    }
}

void expect_box(const TriangleMesh& mesh, const Eigen::Vector3d& min, const Eigen::Vector3d& max, double tolerance) {
  const BoundingBox box = bounding_box(mesh.vertices);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(box.min[k], min[k], tolerance) << "axis " << k;
    EXPECT_NEAR(box.max[k], max[k], tolerance) << "axis " << k;
  }
}

// warnings holds exactly one line per expected fragment, in order, each containing it.
void expect_warnings(const std::vector<std::string>& warnings, const std::vector<std::string>& fragments) {
  ASSERT_EQ(warnings.size(), fragments.size()) << ::testing::PrintToString(warnings);
  for (std::size_t i = 0; i < fragments.size(); ++i)
    EXPECT_NE(warnings[i].find(fragments[i]), std::string::npos) << warnings[i] << " lacks " << fragments[i];
}

// ---- Real files -------------------------------------------------------------------------------

struct RealFile {
  const char* name;
  std::size_t triangles;
  std::size_t vertices;  // distinct positions
  Eigen::Vector3d min, max;
  std::vector<std::string> warnings;
};

class VrmlRealFile : public ::testing::TestWithParam<RealFile> {};

TEST_P(VrmlRealFile, ReadsEveryTriangleOnce) {
  const RealFile& expected = GetParam();
  std::vector<std::string> warnings;
  const TriangleMesh mesh = read_vrml(data_file(expected.name), &warnings);
  expect_well_formed(mesh);
  EXPECT_EQ(mesh.triangles.size(), expected.triangles);
  EXPECT_EQ(mesh.vertices.size(), expected.vertices);
  expect_box(mesh, expected.min, expected.max, 1e-6);  // the files' points are 32-bit floats
  expect_warnings(warnings, expected.warnings);
}

const char* const kTwoSided = "marked solid FALSE";

INSTANTIATE_TEST_SUITE_P(
    Exports, VrmlRealFile,
    ::testing::Values(
        // Switches (whichChoice 0, some choices empty Groups), Normal nodes DEF'd and USE'd.
        RealFile{"choreonoid_DoubleArmV7_block.wrl", 48, 24, {0, 0, -0.2}, {0.2, 0.45, 0}, {}},
        // Transform { scale 0.001 } round the part, which the file gives in millimetres.
        RealFile{"choreonoid_DoubleArmV7_tframe.wrl", 100, 52, {-1.664, -0.225, -0.125}, {0.225, 0.225, 0.125},
                 {std::string("1 geometry node is ") + kTwoSided}},
        // Transform { scale 0.0254 } > Transform { translation -4.1876 -4.1876 -0.593701 }.
        RealFile{"choreonoid_Labo1_valvehandle213.wrl", 332, 156, {-0.10636504, -0.10636504, -0.0150800054},
                 {0.10635996, 0.10635996, 0.0150824946}, {}},
        // Transform { translation -0.31 -0.285 -0.135 scale 0.006 }.
        RealFile{"choreonoid_house_vase.wrl", 2592, 1296, {-0.100438, -0.10074, 1.2e-05}, {0.101018, 0.100728, 0.407118},
                 {std::string("1 geometry node is ") + kTwoSided}},
        // 36 of its 76 Shapes only DEF a Material.
        RealFile{"kicad_stepup_R_0603_1608Metric.wrl", 112, 56, {-0.31496, -0.15748, 0}, {0.31496, 0.15748, 0.177165},
                 {"36 Shapes have no geometry and were skipped"}}),
    [](const auto& case_info) {
      std::string name = case_info.param.name;
      name = name.substr(0, name.find('.'));
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

// tframe's points run from x = -1664 to 225, y = ±225, z = ±125 (read off its Coordinate
// list); Transform { scale 0.001 0.001 0.001 } makes them metres.
TEST(VrmlReader, TransformScaleIsApplied) {
  const TriangleMesh mesh = read_vrml(data_file("choreonoid_DoubleArmV7_tframe.wrl"), nullptr);
  expect_box(mesh, {-1.664, -0.225, -0.125}, {0.225, 0.225, 0.125}, 1e-6);
}

// HelloWorld.wrl came out of the Web3D consortium's X3D-to-VRML97 stylesheet, which kept
// X3D's Viewpoint.centerOfRotation (line 49). VRML97 has no such field, and Coin rejects the
// file there. Decision: that is an InputError at line 49, not a guess. Without that line, Coin
// reads the file: the Sphere (radius 1) is the body, the Text is skipped with a warning.
TEST(VrmlReader, HelloWorldHasAnX3dFieldThatVrml97Lacks) {
  const std::string path = data_file("assimp_HelloWorld.wrl");
  try {
    read_vrml(path, nullptr);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, path);
    EXPECT_EQ(error.where().line, 49);
    EXPECT_NE(error.message().find("centerOfRotation"), std::string::npos) << error.what();
  }
}

// ---- Small files ------------------------------------------------------------------------------

const std::string kHeader = "#VRML V2.0 utf8\n";

// One triangle (0,0,0) (1,0,0) (0,1,0): counter-clockwise seen from +z.
std::string triangle_shape(const std::string& extra = "") {
  return "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } "
         "coordIndex [ 0 1 2 -1 ] " +
         extra + " } }\n";
}

class VrmlFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fabform_vrml_reader_test_" + std::to_string(std::random_device{}()));
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
  TriangleMesh read(const std::string& name, const std::string& text, std::vector<std::string>* warnings = nullptr) {
    return read_vrml(write(name, text), warnings);
  }
  // read_vrml must throw InputError naming the file, at `line` (-1: any line > 0), with a
  // message containing `fragment`.
  void expect_input_error(const std::string& path, int line, const std::string& fragment) {
    try {
      const TriangleMesh mesh = read_vrml(path, nullptr);
      ADD_FAILURE() << "no InputError for " << path << " (" << mesh.triangles.size() << " triangles)";
    } catch (const InputError& error) {
      EXPECT_EQ(error.where().file, path);
      EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
      if (line < 0)
        EXPECT_GT(error.where().line, 0) << error.what();
      else
        EXPECT_EQ(error.where().line, line) << error.what();
      EXPECT_NE(error.message().find(fragment), std::string::npos) << error.what();
    } catch (const std::exception& error) {
      ADD_FAILURE() << "not an InputError: " << error.what();
    }
  }
  fs::path dir_;
};

TEST_F(VrmlFiles, DefUseIsCountedOncePerUse) {
  // One DEF'd triangle used twice more under other translations; a DEF'd Group of two
  // triangles used once more: 3 + 2 × 2 = 7 triangles.
  const TriangleMesh mesh = read("use.wrl", kHeader + "Transform { children DEF T " + triangle_shape() +
                                                "}\n"
                                                "Transform { translation 5 0 0 children USE T }\n"
                                                "Transform { translation 0 5 0 children USE T }\n"
                                                "Transform { translation 0 0 9 children DEF G Group { children [\n"
                                                "  Transform { translation 10 0 0 children USE T }\n"
                                                "  Transform { translation 20 0 0 children USE T } ] } }\n"
                                                "Transform { translation 0 0 -9 children USE G }\n");
  expect_well_formed(mesh);
  EXPECT_EQ(mesh.triangles.size(), 7u);
  EXPECT_EQ(mesh.vertices.size(), 21u);  // no two copies share a position
  expect_box(mesh, {0, 0, -9}, {21, 6, 9}, 0.0);
}

TEST_F(VrmlFiles, SwitchChoiceIsHonoured) {
  const std::string choices = "choice [ Shape { geometry Box { } } " + triangle_shape() + " ] }\n";
  EXPECT_EQ(read("first.wrl", kHeader + "Switch { whichChoice 0 " + choices).triangles.size(), 12u);
  const TriangleMesh second = read("second.wrl", kHeader + "Switch { whichChoice 1 " + choices);
  EXPECT_EQ(second.triangles.size(), 1u);
  expect_box(second, {0, 0, 0}, {1, 1, 0}, 0.0);
  // whichChoice defaults to -1: nothing is drawn.
  expect_input_error(write("none.wrl", kHeader + "Switch { " + choices), 0, "no triangles");
}

TEST_F(VrmlFiles, CcwFalseIsFlipped) {
  const TriangleMesh ccw = read("ccw.wrl", kHeader + triangle_shape());
  ASSERT_EQ(ccw.triangles.size(), 1u);
  EXPECT_GT(area_normal(ccw, ccw.triangles[0]).z(), 0.0);
  const TriangleMesh explicit_ccw = read("ccw_true.wrl", kHeader + triangle_shape("ccw TRUE"));
  EXPECT_GT(area_normal(explicit_ccw, explicit_ccw.triangles[0]).z(), 0.0);

  // The same corners declared clockwise: the front face looks down -z.
  const TriangleMesh cw = read("cw.wrl", kHeader + triangle_shape("ccw FALSE"));
  ASSERT_EQ(cw.triangles.size(), 1u);
  EXPECT_NEAR(area_normal(cw, cw.triangles[0]).z(), -1.0, 1e-15);

  // A quad, triangulated, clockwise: both halves flipped.
  const TriangleMesh quad = read("cw_quad.wrl", kHeader +
                                                    "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, "
                                                    "2 0 0, 2 3 0, 0 3 0 ] } coordIndex [ 0 1 2 3 -1 ] ccw FALSE } }\n");
  ASSERT_EQ(quad.triangles.size(), 2u);
  for (const auto& t : quad.triangles) EXPECT_NEAR(area_normal(quad, t).z(), -6.0, 1e-12);

  // A closed box whose faces are listed clockwise seen from outside, declared ccw FALSE: after
  // the flip its normals point out (positive volume).
  const std::string cube_points = "coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 0 0 1, 1 0 1, 1 1 1, 0 1 1 ] } ";
  const std::string clockwise_faces =
      "coordIndex [ 0 1 2 3 -1, 4 7 6 5 -1, 0 4 5 1 -1, 1 5 6 2 -1, 2 6 7 3 -1, 3 7 4 0 -1 ] ";
  const TriangleMesh cube = read("cw_cube.wrl", kHeader + "Shape { geometry IndexedFaceSet { " + cube_points +
                                                     clockwise_faces + "ccw FALSE } }\n");
  EXPECT_EQ(cube.triangles.size(), 12u);
  EXPECT_NEAR(signed_volume(cube), 1.0, 1e-12);
  // Left at the default (ccw TRUE), the same faces enclose a negative volume: fabform does not
  // reorient what the file declares.
  const TriangleMesh inside_out =
      read("inside_out.wrl", kHeader + "Shape { geometry IndexedFaceSet { " + cube_points + clockwise_faces + "} }\n");
  EXPECT_NEAR(signed_volume(inside_out), -1.0, 1e-12);
}

TEST_F(VrmlFiles, MirroringTransformKeepsTheFrontFace) {
  // scale -1 1 1 mirrors the triangle; its front face still looks toward +z (the normal
  // transforms by the inverse transpose, diag(-1, 1, 1), which leaves (0, 0, 1) alone).
  const TriangleMesh mirrored = read("mirror.wrl", kHeader + "Transform { scale -1 1 1 children " + triangle_shape() + "}\n");
  ASSERT_EQ(mirrored.triangles.size(), 1u);
  expect_box(mirrored, {-1, 0, 0}, {0, 1, 0}, 0.0);
  EXPECT_NEAR(area_normal(mirrored, mirrored.triangles[0]).z(), 1.0, 1e-15);
  const TriangleMesh both =
      read("mirror_cw.wrl", kHeader + "Transform { scale -1 1 1 children " + triangle_shape("ccw FALSE") + "}\n");
  EXPECT_NEAR(area_normal(both, both.triangles[0]).z(), -1.0, 1e-15);
}

// Coin fans every polygon from its first corner unless the face set says convex FALSE, and
// VRML97's default is convex TRUE. An L-shaped hexagon (area 3, reflex corner at (1,1)) listed
// from (2,1): a fan from there gives a triangle folded backwards and covers area 4. read_vrml
// sends every polygon through Coin's tessellator instead.
TEST_F(VrmlFiles, ConcavePolygonsAreTriangulated) {
  const std::string points = "coord Coordinate { point [ 0 0 0, 2 0 0, 2 1 0, 1 1 0, 1 2 0, 0 2 0 ] } ";
  for (const std::string& convex : {std::string(""), std::string("convex TRUE"), std::string("convex FALSE")}) {
    SCOPED_TRACE(convex);
    const TriangleMesh mesh = read("l.wrl", kHeader + "Shape { geometry IndexedFaceSet { " + points +
                                                "coordIndex [ 2 3 4 5 0 1 -1 ] " + convex + " } }\n");
    ASSERT_EQ(mesh.triangles.size(), 4u);  // 6 corners: 6 - 2
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
      const Eigen::Vector3d n = area_normal(mesh, t);
      EXPECT_GE(n.z(), 0.0);  // none folded backwards
      area += 0.5 * n.norm();
    }
    EXPECT_NEAR(area, 3.0, 1e-12);  // none overlapping
  }
  // A U (8 corners, two reflex), as a CAD outline of a slot: 6 triangles covering 3 × 3 - 1 × 2.
  const TriangleMesh u = read("u.wrl", kHeader +
                                           "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 3 0 0, "
                                           "3 3 0, 2 3 0, 2 1 0, 1 1 0, 1 3 0, 0 3 0 ] } coordIndex [ 3 4 5 6 7 0 1 2 ] "
                                           "} }\n");  // the last polygon may end without -1
  ASSERT_EQ(u.triangles.size(), 6u);
  double area = 0.0;
  for (const auto& t : u.triangles) {
    EXPECT_GE(area_normal(u, t).z(), 0.0);
    area += 0.5 * area_normal(u, t).norm();
  }
  EXPECT_NEAR(area, 7.0, 1e-12);
}

TEST_F(VrmlFiles, PrimitivesAreTessellated) {
  std::vector<std::string> warnings;
  const TriangleMesh box = read("box.wrl", kHeader + "Transform { translation 1 2 3 children Shape { geometry Box { size 2 4 6 } } }\n",
                                &warnings);
  expect_well_formed(box);
  EXPECT_EQ(box.triangles.size(), 12u);  // 6 faces, 2 triangles each
  EXPECT_EQ(box.vertices.size(), 8u);
  expect_box(box, {0, 0, 0}, {2, 4, 6}, 0.0);
  EXPECT_NEAR(signed_volume(box), 48.0, 1e-12);  // outward
  EXPECT_TRUE(warnings.empty()) << ::testing::PrintToString(warnings);

  // Coin's own tessellation (at its default complexity: 390, 76 and 38 triangles on Coin
  // 4.0.0); what matters is the shape: the extent, and a volume close to the solid's, positive.
  const double pi = std::acos(-1.0);
  const TriangleMesh sphere = read("sphere.wrl", kHeader + "Shape { geometry Sphere { radius 2 } }\n");
  expect_well_formed(sphere);
  EXPECT_GT(sphere.triangles.size(), 100u);
  expect_box(sphere, {-2, -2, -2}, {2, 2, 2}, 0.05);
  EXPECT_NEAR(signed_volume(sphere) / (4.0 / 3.0 * pi * 8.0), 1.0, 0.05);

  const TriangleMesh cylinder = read("cylinder.wrl", kHeader + "Shape { geometry Cylinder { radius 1 height 2 } }\n");
  EXPECT_GT(cylinder.triangles.size(), 20u);
  expect_box(cylinder, {-1, -1, -1}, {1, 1, 1}, 0.02);
  EXPECT_NEAR(signed_volume(cylinder) / (pi * 2.0), 1.0, 0.05);

  const TriangleMesh cone = read("cone.wrl", kHeader + "Shape { geometry Cone { bottomRadius 1 height 2 } }\n");
  EXPECT_GT(cone.triangles.size(), 10u);
  expect_box(cone, {-1, -1, -1}, {1, 1, 1}, 0.02);
  EXPECT_NEAR(signed_volume(cone) / (pi * 2.0 / 3.0), 1.0, 0.05);
}

TEST_F(VrmlFiles, ExtrusionAndElevationGrid) {
  // A unit square swept 1 along y: 4 sides × 2 + 2 caps × 2 = 12 triangles. This crossSection
  // order gives outward faces with ccw TRUE; the reverse order, declared ccw FALSE, too.
  const TriangleMesh extrusion = read("extrusion.wrl", kHeader +
                                                           "Shape { geometry Extrusion { crossSection [ 0 0, 0 1, 1 1, "
                                                           "1 0, 0 0 ] spine [ 0 0 0, 0 1 0 ] } }\n");
  EXPECT_EQ(extrusion.triangles.size(), 12u);
  EXPECT_NEAR(signed_volume(extrusion), 1.0, 1e-12);
  const TriangleMesh reversed = read("extrusion_cw.wrl", kHeader +
                                                             "Shape { geometry Extrusion { crossSection [ 0 0, 1 0, 1 1, "
                                                             "0 1, 0 0 ] spine [ 0 0 0, 0 1 0 ] ccw FALSE } }\n");
  EXPECT_NEAR(signed_volume(reversed), 1.0, 1e-12);

  // 3 × 3 heights: 2 × 2 cells, 2 triangles each, facing +y.
  const TriangleMesh grid = read("grid.wrl", kHeader +
                                                 "Shape { geometry ElevationGrid { xDimension 3 zDimension 3 "
                                                 "xSpacing 0.5 zSpacing 0.5 height [ 0 0 0, 0 1 0, 0 0 0 ] } }\n");
  EXPECT_EQ(grid.triangles.size(), 8u);
  expect_box(grid, {0, 0, 0}, {1, 1, 1}, 0.0);
  for (const auto& t : grid.triangles) EXPECT_GT(area_normal(grid, t).y(), 0.0);
  expect_input_error(write("short_grid.wrl", kHeader + "Shape { geometry ElevationGrid { xDimension 3 zDimension 3 "
                                                       "height [ 0 0 0 ] } }\n"),
                     0, "ElevationGrid has 3 heights for 3 x 3 points");
}

TEST_F(VrmlFiles, WarningsSaySkippedContent) {
  std::vector<std::string> warnings{"kept"};  // appended to, not replaced
  const TriangleMesh mesh = read("mixed.wrl",
                                 kHeader + triangle_shape() + "Shape { appearance Appearance { } }\nShape { }\n" +
                                     "Shape { geometry Text { string [ \"label\" ] } }\n"
                                     "Shape { geometry IndexedLineSet { coord Coordinate { point [ 0 0 0, 1 0 0 ] } "
                                     "coordIndex [ 0 1 -1 ] } }\n"
                                     "Shape { geometry PointSet { coord Coordinate { point [ 0 0 0 ] } } }\n"
                                     "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0 ] } } }\n" +
                                     triangle_shape("solid FALSE"),
                                 &warnings);
  EXPECT_EQ(mesh.triangles.size(), 2u);
  expect_warnings(warnings, {"kept", "2 Shapes have no geometry and were skipped",
                             "skipped text (1 Text): text is not a surface of the body",
                             "skipped 1 IndexedLineSet, 1 PointSet: lines and points have no faces",
                             "no triangles from 1 IndexedFaceSet",
                             "1 geometry node is marked solid FALSE (two-sided)"});
}

// An assembly that Inlines its parts: they are read from the assembly's own directory (not the
// working directory), once per Inline.
TEST_F(VrmlFiles, InlinedPartsAreRead) {
  fs::create_directories(dir_ / "parts");
  write("parts/cube.wrl", kHeader + "Shape { geometry Box { } }\n");
  const std::string assembly = write("parts/assembly.wrl", kHeader +
                                                               "Inline { url \"cube.wrl\" }\n"
                                                               "Transform { translation 5 0 0 children Inline { url \"cube.wrl\" } }\n");
  ASSERT_NE(fs::current_path(), dir_ / "parts");
  const TriangleMesh mesh = read_vrml(assembly, nullptr);
  EXPECT_EQ(mesh.triangles.size(), 24u);
  expect_box(mesh, {-1, -1, -1}, {6, 1, 1}, 0.0);
  // A part that is not there is a part of the body missing.
  expect_input_error(write("parts/incomplete.wrl", kHeader + "\nInline { url \"lost.wrl\" }\n"), 0,
                     "Inline 'lost.wrl': no such local file");
  // Coin, left to itself, recursed without end on these (a stack overflow).
  expect_input_error(write("parts/itself.wrl", kHeader + "Inline { url \"itself.wrl\" }\n"), 0, "Inline cycle");
  write("parts/b.wrl", kHeader + "Inline { url \"a.wrl\" }\n");
  const std::string a = write("parts/a.wrl", kHeader + "Inline { url \"b.wrl\" }\n");
  try {
    read_vrml(a, nullptr);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, fs::canonical(dir_ / "parts" / "b.wrl").string());  // where the cycle closes
    EXPECT_NE(error.message().find("Inline cycle"), std::string::npos) << error.what();
  }
  // An error inside an inlined part names that part and its line.
  const std::string broken = write("parts/broken.wrl", kHeader + "\nShape { geometry Box { size 1 1 } }\n");
  try {
    read_vrml(write("parts/uses_broken.wrl", kHeader + "Inline { url \"broken.wrl\" }\n"), nullptr);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(fs::canonical(error.where().file), fs::canonical(broken));
    EXPECT_EQ(error.where().line, 3) << error.what();
  }
}

// The HelloWorld decision above, checked the other way: without the X3D-only field the file
// reads, and only its Sphere counts.
TEST_F(VrmlFiles, HelloWorldWithoutTheX3dField) {
  std::string text = slurp(data_file("assimp_HelloWorld.wrl"));
  const std::size_t at = text.find("        centerOfRotation 0 -1 0\n");
  ASSERT_NE(at, std::string::npos);
  text.erase(at, std::string("        centerOfRotation 0 -1 0\n").size());
  std::vector<std::string> warnings;
  const TriangleMesh sphere = read("hello.wrl", text, &warnings);
  // A unit Sphere under Transform { rotation 0 1 0 3 }: a rotation leaves it a unit sphere.
  expect_box(sphere, {-1, -1, -1}, {1, 1, 1}, 0.03);
  EXPECT_NEAR(signed_volume(sphere) / (4.0 / 3.0 * std::acos(-1.0)), 1.0, 0.05);
  expect_warnings(warnings, {"skipped text (1 Text): text is not a surface of the body",
                             "hello.wrl:64: Could not read texture file: earth-topo.png (textures do not matter to the body)"});
}

// ---- Files that are not VRML97, or broken -----------------------------------------------------

TEST_F(VrmlFiles, HeaderlessFileNamesTheFile) {
  // A real fragment meant to be Inline'd: no '#VRML V2.0 utf8' line.
  const std::string path = data_file("choreonoid_PA10_J2_no_header.wrl");
  expect_input_error(path, 1, "#VRML V2.0 utf8");
  // The same bytes behind the header are a good file: 96 triangles (tests/data/vrml/README.md).
  EXPECT_EQ(read("with_header.wrl", kHeader + slurp(path)).triangles.size(), 96u);
}

TEST_F(VrmlFiles, OtherHeadersAreRefused) {
  expect_input_error(write("v1.wrl", "#VRML V1.0 ascii\nSeparator { Cube { } }\n"), 1, "#VRML V1.0 ascii");
  expect_input_error(write("inventor.wrl", "#Inventor V2.1 ascii\nSeparator { Cube { } }\n"), 1, "#Inventor V2.1");
  expect_input_error(write("x3dv.wrl", slurp(data_file("x3d/assimp_HelloWorld.x3dv"))), 1, "not a VRML97 file");
}

TEST_F(VrmlFiles, TruncatedFileNamesItsLastLine) {
  const std::string text = slurp(data_file("choreonoid_DoubleArmV7_tframe.wrl")).substr(0, 5000);
  const int lines = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  expect_input_error(write("truncated.wrl", text), lines, "cannot read VRML");
}

TEST_F(VrmlFiles, GarbageNamesTheLine) {
  expect_input_error(write("garbage.wrl", kHeader + "\n%$@!! garbage {{{ \x01\x02\n"), 3, "cannot read VRML");
  std::string bytes(300, '\0');
  for (std::size_t k = 0; k < bytes.size(); ++k) bytes[k] = static_cast<char>((k * 37 + 11) % 251);
  expect_input_error(write("binary.wrl", bytes), 1, "not a VRML97 file");
  expect_input_error(write("binary_after_header.wrl", kHeader + bytes), -1, "cannot read VRML");
  expect_input_error(write("unknown_field.wrl", kHeader + "\n" + triangle_shape("foo 3")), 3, "Unknown field \"foo\"");
  expect_input_error(write("unknown_use.wrl", kHeader + "Shape { geometry USE nothing }\n"), 2, "nothing");
  // Coin would read 1e39 as 0 after an error message; fabform stops there.
  expect_input_error(write("overflow.wrl", kHeader + "Shape { geometry IndexedFaceSet { coord Coordinate {\n"
                                                     "point [ 0 0 0, 1 0 1e39, 0 1 0 ] } coordIndex [ 0 1 2 -1 ] } }\n"),
                     3, "cannot read VRML");
}

TEST_F(VrmlFiles, EmptyAndMissingFiles) {
  expect_input_error(write("empty.wrl", ""), 0, "empty file");
  expect_input_error((dir_ / "nothing_here.wrl").string(), 0, "no such mesh file");
  fs::create_directories(dir_ / "folder.wrl");
  expect_input_error((dir_ / "folder.wrl").string(), 0, "no such mesh file");
}

TEST_F(VrmlFiles, NoTrianglesIsAnError) {
  // Shapes that only define materials, as the KiCad export has 36 of.
  expect_input_error(write("materials_only.wrl", kHeader + "Shape { appearance Appearance { material DEF M Material { } } }\n"
                                                           "Shape { appearance Appearance { material USE M } }\n"),
                     0, "no triangles; 2 Shapes have no geometry");
  expect_input_error(write("header_only.wrl", kHeader), 0, "no triangles");
  expect_input_error(write("lines_only.wrl", kHeader + "Shape { geometry IndexedLineSet { coord Coordinate { point "
                                                       "[ 0 0 0, 1 0 0 ] } coordIndex [ 0 1 -1 ] } }\n"),
                     0, "lines and points have no faces");
}

TEST_F(VrmlFiles, IndexOutOfRangeIsAnError) {
  // Coin does not check coordIndex: it would read past the three points.
  expect_input_error(write("index.wrl", kHeader + "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, "
                                                  "1 0 0, 0 1 0 ] } coordIndex [ 0 1 7 -1 ] } }\n"),
                     0, "coordIndex 7 (entry 2) is out of range: its Coordinate has 3 points");
  expect_input_error(write("negative.wrl", kHeader + "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, "
                                                     "1 0 0, 0 1 0 ] } coordIndex [ 0 1 -2 -1 ] } }\n"),
                     0, "coordIndex -2");
  // A bad normalIndex does not matter: normals are not read.
  EXPECT_EQ(read("normals.wrl", kHeader + "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, "
                                          "0 1 0 ] } coordIndex [ 0 1 2 -1 ] normal Normal { vector [ 0 0 1 ] } "
                                          "normalIndex [ 0 0 99 -1 ] } }\n")
                .triangles.size(),
            1u);
}

// ---- Through read_mesh ------------------------------------------------------------------------

TEST_F(VrmlFiles, ReadMeshSendsVrmlToCoin) {
  const std::string text = slurp(data_file("choreonoid_DoubleArmV7_tframe.wrl"));
  for (const char* name : {"tframe.wrl", "TFRAME.WRL", "tframe.Wrl", "tframe.vrml"}) {
    std::vector<std::string> warnings;
    EXPECT_EQ(read_mesh(write(name, text), &warnings).triangles.size(), 100u) << name;
    EXPECT_EQ(warnings.size(), 1u) << name;  // solid FALSE
  }
  EXPECT_EQ(read_mesh(write("default_warnings.wrl", text)).triangles.size(), 100u);

  // .wrz is gzip-compressed VRML97: these bytes are gzip of "#VRML V2.0 utf8\nShape { geometry Box { } }\n".
  const unsigned char gz[] = {0x1f, 0x8b, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0xff, 0x53, 0x0e, 0x0b, 0xf2, 0xf5, 0x51,
                              0x08, 0x33, 0xd2, 0x33, 0x50, 0x28, 0x2d, 0x49, 0xb3, 0xe0, 0x0a, 0xce, 0x48, 0x2c, 0x48, 0x55,
                              0xa8, 0x56, 0x48, 0x4f, 0xcd, 0xcf, 0x4d, 0x2d, 0x29, 0xaa, 0x54, 0x70, 0xca, 0xaf, 0x00, 0x72,
                              0x6b, 0x15, 0x6a, 0xb9, 0x00, 0xf8, 0x2a, 0x5a, 0x38, 0x2b, 0x00, 0x00, 0x00};
  const TriangleMesh box = read_mesh(write("box.wrz", std::string(reinterpret_cast<const char*>(gz), sizeof gz)));
  EXPECT_EQ(box.triangles.size(), 12u);
  expect_box(box, {-1, -1, -1}, {1, 1, 1}, 0.0);
}

// X3D XML is translated (tests/io/x3d_translation_test.cpp); its other encodings are refused.
TEST(VrmlReader, X3dClassicEncodingIsRefused) {
  const std::string path = data_file("x3d/assimp_HelloWorld.x3dv");
  try {
    read_mesh(path);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, path);
    EXPECT_NE(error.message().find("X3D's classic and binary encodings are not read"), std::string::npos) << error.what();
  }
}

// ---- Coin, wrapped ----------------------------------------------------------------------------

// Coin's default handlers print its errors and warnings; read_vrml captures them all.
TEST_F(VrmlFiles, CoinPrintsNothing) {
  std::vector<std::string> paths;
  for (const auto& entry : fs::directory_iterator(test::source_path("tests/data/vrml")))
    if (entry.path().extension() == ".wrl") paths.push_back(entry.path().string());
  paths.push_back(write("garbage.wrl", kHeader + "%$@!! {{{\n"));
  paths.push_back(write("overflow.wrl", kHeader + "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 1e39 0 0 ] } } }\n"));
  paths.push_back(write("v1.wrl", "#VRML V1.0 ascii\nSeparator { Cube { } }\n"));
  paths.push_back(write("empty.wrl", ""));

  const std::string captured = (dir_ / "captured.txt").string();
  std::fflush(stdout);
  std::fflush(stderr);
  const int saved_out = dup(1), saved_err = dup(2);
  FILE* sink = std::fopen(captured.c_str(), "w");
  ASSERT_NE(sink, nullptr);
  dup2(fileno(sink), 1);
  dup2(fileno(sink), 2);
  int read_ok = 0, refused = 0;
  for (const std::string& path : paths) {
    try {
      read_vrml(path, nullptr);
      ++read_ok;
    } catch (const InputError&) {
      ++refused;
    }
  }
  std::fflush(stdout);
  std::fflush(stderr);
  dup2(saved_out, 1);
  dup2(saved_err, 2);
  close(saved_out);
  close(saved_err);
  std::fclose(sink);
  EXPECT_EQ(read_ok, 5);
  EXPECT_EQ(refused, 6);
  EXPECT_EQ(slurp(captured), "");
}

TEST(VrmlReader, ConcurrentReadsAgree) {
  const std::vector<std::pair<std::string, std::size_t>> files{{"choreonoid_house_vase.wrl", 2592},
                                                               {"choreonoid_Labo1_valvehandle213.wrl", 332},
                                                               {"kicad_stepup_R_0603_1608Metric.wrl", 112}};
  std::vector<std::thread> threads;
  std::vector<int> wrong(6, 0);
  for (std::size_t k = 0; k < wrong.size(); ++k)
    threads.emplace_back([&, k] {
      for (int round = 0; round < 5; ++round) {
        const auto& [name, triangles] = files[(k + static_cast<std::size_t>(round)) % files.size()];
        std::vector<std::string> warnings;
        if (read_vrml(data_file(name), &warnings).triangles.size() != triangles) ++wrong[k];
        try {  // errors in one thread do not leak into another's read
          read_vrml(data_file("assimp_HelloWorld.wrl"), nullptr);
          ++wrong[k];
        } catch (const InputError& error) {
          if (error.where().line != 49) ++wrong[k];
        }
      }
    });
  for (auto& t : threads) t.join();
  for (const int w : wrong) EXPECT_EQ(w, 0);
}

}  // namespace
}  // namespace fabform::vrml_reader_test
