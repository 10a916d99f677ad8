// One body in VRML97 as CAD exports it: shapes under nested Transforms that translate, rotate,
// scale non-uniformly (with a scaleOrientation), mirror, and a geometry DEF'd once and USE'd
// under another Transform. Every vertex is where VRML97's transform (T C R SR S -SR -C, composed
// outermost first) puts it, computed here in double from the file's numbers (Coin composes in
// float: within 1e-6 of the size); each part is closed and faces outward with the scaled volume;
// and `fabform check --repair`'s path (repair, write OBJ, read back) changes nothing: the issue
// 24 file came back moved and with non-manifold edges when OBJ was read in float.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "fabform/geometry/mesh_repair.hpp"
#include "fabform/geometry/mesh_report.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "fabform/io/obj_text.hpp"
#include "support/temp_dir.hpp"

namespace fabform::vrml_transform_test {
namespace {

using V3 = Eigen::Vector3d;
using Affine = Eigen::Affine3d;

struct TransformFields {
  V3 translation = V3::Zero();
  V3 rotation_axis = V3::UnitZ();
  double rotation = 0.0;
  V3 scale = V3::Ones();
  V3 scale_axis = V3::UnitZ();
  double scale_angle = 0.0;
  V3 center = V3::Zero();

  std::string vrml() const {
    char text[1024];  // 17 numbers of up to 24 characters each, and the words
    std::snprintf(text, sizeof text,
                  "Transform { translation %.17g %.17g %.17g rotation %.17g %.17g %.17g %.17g scale %.17g %.17g %.17g "
                  "scaleOrientation %.17g %.17g %.17g %.17g center %.17g %.17g %.17g children [",
                  translation.x(), translation.y(), translation.z(), rotation_axis.x(), rotation_axis.y(), rotation_axis.z(),
                  rotation, scale.x(), scale.y(), scale.z(), scale_axis.x(), scale_axis.y(), scale_axis.z(), scale_angle,
                  center.x(), center.y(), center.z());
    return text;
  }

  // VRML97 §6.52: P' = T × C × R × SR × S × -SR × -C × P.
  Affine matrix() const {
    const Eigen::AngleAxisd r(rotation, rotation_axis.normalized()), sr(scale_angle, scale_axis.normalized());
    return Eigen::Translation3d(translation) * Eigen::Translation3d(center) * r * sr * Eigen::Scaling(scale) *
           sr.inverse() * Eigen::Translation3d(-center);
  }
};

// A unit cube's corners and outward quads (counter-clockwise seen from outside).
const V3 kCorners[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const char* const kCubeFaces = "coordIndex [ 0 3 2 1 -1, 4 5 6 7 -1, 0 1 5 4 -1, 1 2 6 5 -1, 2 3 7 6 -1, 3 0 4 7 -1 ]";

std::string cube_coordinates() {
  std::string text = "coord Coordinate { point [";
  for (const V3& c : kCorners) text += " " + std::to_string(c.x()) + " " + std::to_string(c.y()) + " " + std::to_string(c.z()) + ",";
  return text + " ] }";
}

struct Body {
  std::string vrml;
  std::vector<V3> expected;  // every corner where VRML97 puts it
  double volume = 0.0;
};

// Outer (rotated, non-uniformly scaled, far from the origin) > inner (rotated about a centre,
// scaled along a turned axis) > the DEF'd cube; beside it, a mirrored Transform USEs the cube.
Body nested_body() {
  TransformFields outer, inner, mirror;
  outer.translation = {1234.5, -80.25, 17.0};
  outer.rotation_axis = {0.3, 0.2, 0.9};
  outer.rotation = 0.77;
  outer.scale = {25.4, 12.7, 50.8};
  inner.translation = {1, 2, 3};
  inner.rotation_axis = {1, 1, 0};
  inner.rotation = 1.1;
  inner.scale = {1, 3, 0.5};
  inner.scale_axis = {0, 1, 0};
  inner.scale_angle = 0.4;
  inner.center = {0.5, 0.5, 0.5};
  mirror.translation = {8, 0, 0};
  mirror.scale = {-1, 2, 1};  // mirrors: the reader must turn the faces back outward
  mirror.rotation_axis = {0, 0, 1};
  mirror.rotation = 0.3;
  Body body;
  body.vrml = "#VRML V2.0 utf8\n" + outer.vrml() + "\n  " + inner.vrml() +
              "\n    Shape { geometry DEF CUBE IndexedFaceSet { " + cube_coordinates() + " " + kCubeFaces + " } }\n  ] }\n  " +
              mirror.vrml() + "\n    Shape { geometry USE CUBE }\n  ] }\n] }\n";
  for (const Affine& m : {outer.matrix() * inner.matrix(), outer.matrix() * mirror.matrix()}) {
    for (const V3& c : kCorners) body.expected.push_back(m * c);
    body.volume += std::abs(m.linear().determinant());
  }
  return body;
}

TEST(VrmlTransforms, NestedRotatedScaledAndMirroredPartsAreWhereVrmlPutsThem) {
  const test::TempDir dir;
  const Body body = nested_body();
  const TriangleMesh mesh = read_mesh(dir.write("body.wrl", body.vrml));
  ASSERT_EQ(mesh.vertices.size(), 16u);
  ASSERT_EQ(mesh.triangles.size(), 24u);
  const double tolerance = 1e-6 * bounding_box(body.expected).diagonal();
  for (const V3& e : body.expected) {
    double nearest = 1e300;
    for (const V3& v : mesh.vertices) nearest = std::min(nearest, (v - e).norm());
    EXPECT_LE(nearest, tolerance) << e.transpose();
  }
  const MeshReport r = inspect_mesh(mesh);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.components, 2);
  EXPECT_EQ(r.orientation, MeshOrientation::outward);
  EXPECT_NEAR(r.signed_volume, body.volume, 1e-5 * body.volume);
  EXPECT_TRUE(r.usable_for_contact());
}

TEST(VrmlTransforms, RepairWriteAndReadBackChangeNothing) {
  const test::TempDir dir;
  const TriangleMesh mesh = read_mesh(dir.write("body.wrl", nested_body().vrml));
  const RepairResult repaired = repair_mesh(mesh);
  EXPECT_FALSE(repaired.changed());
  const TriangleMesh back = read_mesh(dir.write("repaired.obj", obj_text(repaired.mesh)));
  ASSERT_EQ(back.vertices.size(), mesh.vertices.size());
  for (const V3& v : mesh.vertices)
    EXPECT_NE(std::find(back.vertices.begin(), back.vertices.end(), v), back.vertices.end())
        << "moved: " << v.transpose();
  const MeshReport before = inspect_mesh(mesh), after = inspect_mesh(back);
  EXPECT_EQ(after.non_manifold_edges, 0);
  EXPECT_EQ(after.orientation, before.orientation);
  EXPECT_EQ(after.box.min, before.box.min);
  EXPECT_EQ(after.box.max, before.box.max);
  EXPECT_EQ(after.signed_volume, before.signed_volume);
}

}  // namespace
}  // namespace fabform::vrml_transform_test
