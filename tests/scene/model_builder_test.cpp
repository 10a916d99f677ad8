// From a scene to a model: the files it names are read, and what cannot be used is reported
// with the file and line to fix.
#include "fabform/scene/model_builder.hpp"

#include <filesystem>

#include <gtest/gtest.h>


#include "fabform/io/obj_text.hpp"
#include "fabform/model/equilibrium.hpp"
#include "fabform/model/gravity.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/relax.hpp"
#include "support/shapes.hpp"
#include "support/terms.hpp"
#include "support/scene_models.hpp"
#include "support/temp_dir.hpp"

namespace fabform::model_builder_test {
namespace {

// A 10 × 10 cm fabric lifted 2 cm over a 3 cm sphere whose top reaches 1 cm.
class ModelBuilder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("table.csv", "strain,tension_N_per_m\n0,0\n1,500\n");
    dir.write("sphere.obj", obj_text(test::uv_sphere({0.05, 0.05, -0.02}, 0.03, 20, 40)));
  }
  std::string scene(const std::string& extra, const std::string& lift = "0.02") const {
    return "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [10, 10]\n"
           "warp = \"table.csv\"\nweft = \"table.csv\"\n"
           "[[body]]\nmesh = \"sphere.obj\"\nunits = \"m\"\n"
           "[initial]\nshape = \"lift\"\nheight_m = " + lift + "\n" + extra;
  }
  Model build(const std::string& text) const { return test::build_scene(dir, text); }
  InputError error(const std::string& text) const { return test::scene_error(dir, text); }
  test::TempDir dir;
};

TEST_F(ModelBuilder, BuildsLocksBodiesAndStart) {
  const Model model = build(scene("[[constraint]]\nnodes = \"perimeter\"\n[[constraint]]\nnode = [5, 5]\naxes = \"z\"\n"));
  EXPECT_EQ(model.node_count(), 121);
  EXPECT_EQ(model.bodies.size(), 1u);
  EXPECT_EQ(model.locks[static_cast<std::size_t>(model.fabric.node(0, 3))], kLockX | kLockY | kLockZ);
  EXPECT_EQ(model.locks[static_cast<std::size_t>(model.fabric.node(5, 5))], kLockZ);
  EXPECT_EQ(model.locks[static_cast<std::size_t>(model.fabric.node(4, 5))], 0);
  EXPECT_DOUBLE_EQ(model.start[static_cast<std::size_t>(model.fabric.node(5, 5))].z(), 0.02);
}

TEST_F(ModelBuilder, NodeSetThatSelectsNothing) {
  const InputError e = error(scene("[[constraint]]\nbox_m = [[0.2, 0.2], [0.3, 0.3]]\n"));
  EXPECT_EQ(e.where().line, 12);
  EXPECT_NE(std::string(e.what()).find("selects no node"), std::string::npos) << e.what();
  const InputError index = error(scene("[[constraint]]\nnode = [11, 0]\n"));
  EXPECT_NE(std::string(index.what()).find("selects no node"), std::string::npos) << index.what();
}

// A blank holder locks its nodes in z and shares its force by area; one that grips nothing is
// refused at its table.
TEST_F(ModelBuilder, AClampHoldsItsFrameInZ) {
  const Model model = build(scene("[clamp]\nwidth_m = 0.01\nforce_N = 10\nfriction = 0.3\n[solver]\nname = \"newton\"\n"));
  for (int k = 0; k < model.node_count(); ++k) {
    const int i = model.fabric.i_of(k), j = model.fabric.j_of(k);
    const bool frame = std::min({i, j, 10 - i, 10 - j}) <= 1;  // 1 cm of 1 cm cells
    EXPECT_EQ(model.locks[static_cast<std::size_t>(k)], frame ? kLockZ : 0) << i << ", " << j;
  }
  const InputError e = error(scene("[clamp]\nbox_m = [[0.2, 0.2], [0.3, 0.3]]\nforce_N = 10\nfriction = 0.3\n"
                                   "[solver]\nname = \"newton\"\n"));
  EXPECT_EQ(e.where().key, "clamp");
  EXPECT_EQ(e.where().line, 12);
  EXPECT_NE(std::string(e.what()).find("selects no node"), std::string::npos) << e.what();
}

// A tolerance relative to the force scale becomes newtons once the tables are known; tables
// that start slack have no scale, and the key is named.
TEST_F(ModelBuilder, RelativeToleranceBecomesNewtons) {
  const std::string relative = scene("[solver]\ntolerance_relative = 1e-3\n");
  const Scene written = load_scene(dir.write("scene.toml", relative));
  const Model model = build_model(written);
  EXPECT_NEAR(with_tolerance_in_newtons(written, model).solver.tolerance_N(), 1e-3 * 0.5 * 0.01 * 500.0, 1e-15);
  dir.write("table.csv", "strain,tension_N_per_m\n0,0\n0.1,0\n1,500\n");
  const Scene slack = load_scene(dir.write("scene.toml", relative));
  try {
    with_tolerance_in_newtons(slack, build_model(slack));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "solver.tolerance_relative");
    EXPECT_EQ(e.where().line, 13);
    EXPECT_NE(std::string(e.what()).find("start slack"), std::string::npos) << e.what();
  }
}

TEST_F(ModelBuilder, FabricStartingInsideTheBody) {
  const InputError e = error(scene("", "0.005"));
  EXPECT_NE(std::string(e.what()).find("inside body"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().key, "initial");
}

TEST_F(ModelBuilder, SpringThroughTheBody) {
  // Nodes clear of a thin sphere but a spring crossing it: a 1 mm sphere between two nodes.
  dir.write("sphere.obj", obj_text(test::uv_sphere({0.025, 0.05, 0.0}, 0.001, 8, 16)));
  std::string text = scene("");
  text.replace(text.find("shape = \"lift\""), 14, "shape = \"flat\"");
  const InputError e = error(text);
  EXPECT_NE(std::string(e.what()).find("passes through body"), std::string::npos) << e.what();
}

TEST_F(ModelBuilder, DecreasingTableNamesFileAndLine) {
  const std::string table = dir.write("table.csv", "strain,tension_N_per_m\n0,0\n0.5,10\n0.4,20\n");
  const InputError e = error(scene(""));
  EXPECT_EQ(e.where().file, table);
  EXPECT_EQ(e.where().line, 4);
}

TEST_F(ModelBuilder, MeshWithoutTrianglesNamesTheMesh) {
  const std::string mesh = dir.write("sphere.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  const InputError e = error(scene(""));
  EXPECT_EQ(e.where().file, mesh);
}

TEST_F(ModelBuilder, MissingFilesAreBlamedOnTheSceneKey) {
  std::filesystem::remove(dir.path("table.csv"));
  const InputError table = error(scene(""));
  EXPECT_EQ(table.where().file, dir.path("scene.toml"));
  EXPECT_EQ(table.where().key, "fabric.warp");
  EXPECT_EQ(table.where().line, 4);
  EXPECT_NE(std::string(table.what()).find(dir.path("table.csv")), std::string::npos);
  dir.write("table.csv", "strain,tension_N_per_m\n0,0\n1,500\n");
  std::filesystem::remove(dir.path("sphere.obj"));
  const InputError mesh = error(scene(""));
  EXPECT_EQ(mesh.where().key, "body.0.mesh");
  EXPECT_EQ(mesh.where().line, 7);
}

TEST_F(ModelBuilder, CoordinatesBeyondAThousandKilometresAreAUnitMistake) {
  const InputError body = error(scene("") + "[[body]]\nmesh = \"sphere.obj\"\nunits = \"m\"\n"
                                             "translation_m = [1e39, 0, 0]\n");
  EXPECT_EQ(body.where().key, "body.1");
  const InputError fabric = error(scene("", "1e200"));
  EXPECT_EQ(fabric.where().key, "initial");
}

TEST_F(ModelBuilder, InvertedMeshIsNamedAsSuch) {
  TriangleMesh sphere = test::uv_sphere({0.05, 0.05, -0.02}, 0.03, 20, 40);
  for (auto& t : sphere.triangles) std::swap(t[1], t[2]);
  dir.write("sphere.obj", obj_text(sphere));
  const InputError e = error(scene(""));
  EXPECT_NE(std::string(e.what()).find("faces point inward"), std::string::npos) << e.what();
}

// A mold and a second body in one scene, each in its own units and placement: two spheres
// whose tops poke 1 cm through the clamped fabric's plane, one written in millimetres and
// moved, one in centimetres, scaled and turned about its own centre line. The fabric, lifted
// clear of both, comes to rest on both and enters neither.
TEST_F(ModelBuilder, TwoBodiesInTheirOwnUnitsBothHoldTheFabric) {
  dir.write("left_mm.obj", obj_text(test::uv_sphere({0, 0, 0}, 20.0, 20, 40)));
  dir.write("right_cm.obj", obj_text(test::uv_sphere({0, 0, 0}, 1.0, 20, 40)));
  const std::string text =
      "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [20, 20]\nwarp = \"table.csv\"\nweft = \"table.csv\"\n"
      "[[body]]\nname = \"left\"\nmesh = \"left_mm.obj\"\nunits = \"mm\"\ntranslation_m = [0.03, 0.05, -0.01]\n"
      "[[body]]\nname = \"right\"\nmesh = \"right_cm.obj\"\nunits = \"cm\"\nscale = 2.0\n"
      "rotation_deg = [0, 0, 90]\ntranslation_m = [0.07, 0.05, -0.01]\n"
      "[[constraint]]\nnodes = \"perimeter\"\n[initial]\nshape = \"lift\"\nheight_m = 0.03\n";
  const Model model = build(text);
  ASSERT_EQ(model.bodies.size(), 2u);
  for (const RigidBody& body : model.bodies) {  // both are 4 cm spheres centred 1 cm below the plane
    EXPECT_NEAR(body.box().max.z(), 0.01, 1e-12) << body.name();
    EXPECT_NEAR(body.box().max.x() - body.box().min.x(), 0.04, 1e-3) << body.name();
  }
  SolverState state = SolverState::at_start(model);
  RelaxOptions options;
  options.tolerance_N = 1e-4;
  const Summary summary = relax(model, state, options);
  ASSERT_TRUE(summary.converged()) << summary.message;
  int on_body[2] = {0, 0};
  for (const NodeContact& c : state.contact)
    if (c.active()) ++on_body[c.body];
  EXPECT_GT(on_body[0], 0);
  EXPECT_GT(on_body[1], 0);
  const EquilibriumReport check = measure_equilibrium(model, state.x, 1e-8);
  EXPECT_LE(check.max_residual_N, options.tolerance_N);
  EXPECT_LE(check.max_penetration_m, 1e-9);  // the projections' rounding, far below a facet
}

// A coarser grid of the same scene (grid continuation) takes the bodies as the scene's model
// placed them, without reading the mesh again: it builds with the file gone, to the same mesh.
TEST_F(ModelBuilder, AnotherGridTakesTheBodiesAsPlaced) {
  const Scene fine = load_scene(dir.write("scene.toml", scene("")));
  const Model placed = build_model(fine);
  std::filesystem::remove(dir.path("sphere.obj"));
  Scene coarse = fine;
  coarse.fabric.divisions_warp = coarse.fabric.divisions_weft = 5;
  const Model level = build_model(coarse, &placed);
  EXPECT_EQ(level.node_count(), 36);
  ASSERT_EQ(level.bodies.size(), 1u);
  EXPECT_EQ(level.bodies[0].mesh().vertices, placed.bodies[0].mesh().vertices);
  EXPECT_EQ(level.bodies[0].mesh().triangles, placed.bodies[0].mesh().triangles);
  EXPECT_EQ(level.bodies[0].name(), placed.bodies[0].name());
  EXPECT_THROW(build_model(coarse), InputError);  // read again, the missing file is the scene's error
}

// Gravity weighs the fabric with the density its material files state; it is said in `modelled`.
TEST_F(ModelBuilder, GravityWeighsTheFabricWithTheMaterialsDensity) {
  dir.write("table.csv", "areal_density_kg_m2,0.25\nstrain,tension_N_per_m\n0,0\n1,500\n");
  const Model model = build(scene("[gravity]\nacceleration_m_s2 = 9.81\n"));
  const Gravity* gravity = test::find_term<Gravity>(model);
  ASSERT_NE(gravity, nullptr);
  ASSERT_EQ(gravity->loads().size(), static_cast<std::size_t>(model.node_count()));
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const auto& f : gravity->loads()) total += f;
  EXPECT_NEAR(total.z(), -0.25 * 0.01 * 9.81, 1e-12 * 0.25 * 0.01 * 9.81);
  EXPECT_EQ(total.head<2>().norm(), 0.0);
  const std::vector<std::string> modelled = model.modelled();
  ASSERT_EQ(modelled.size(), 2u);
  EXPECT_NE(modelled[1].find("gravity: 9.81 m/s²"), std::string::npos) << modelled[1];
  EXPECT_NE(modelled[1].find("0.25 kg/m²"), std::string::npos) << modelled[1];
  EXPECT_TRUE(model.loaded());
}

TEST_F(ModelBuilder, NoGravityNoLoads) {
  const Model model = build(scene(""));
  EXPECT_FALSE(model.loaded());
  EXPECT_EQ(test::find_term<Gravity>(model), nullptr);
  ASSERT_EQ(model.modelled().size(), 1u);
  EXPECT_EQ(model.modelled()[0].rfind("stretch: warp and weft springs of a rectangle", 0), 0u) << model.modelled()[0];
}

TEST_F(ModelBuilder, GravityWithoutADensityIsBlamedOnTheGravityTable) {
  const InputError e = error(scene("[gravity]\n"));
  EXPECT_EQ(e.where().line, 12) << e.what();
  EXPECT_NE(std::string(e.what()).find("gravity needs the fabric's mass per area: give fabric.areal_mass_g_m2"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("areal_density_kg_m2"), std::string::npos) << e.what();
}

TEST_F(ModelBuilder, WarpAndWeftDensitiesMustAgree) {
  dir.write("warp.csv", "areal_density_kg_m2,0.25\nstrain,tension_N_per_m\n0,0\n1,500\n");
  dir.write("weft.csv", "areal_density_kg_m2,0.3\nstrain,tension_N_per_m\n0,0\n1,500\n");
  std::string text = scene("[gravity]\n");
  const std::string tables = "warp = \"table.csv\"\nweft = \"table.csv\"";
  text.replace(text.find(tables), tables.size(), "warp = \"warp.csv\"\nweft = \"weft.csv\"");
  const InputError e = error(text);
  EXPECT_NE(e.where().file.find("weft.csv"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().line, 1) << e.what();
  EXPECT_NE(std::string(e.what()).find("0.29999999999999999 differs from 0.25 in the warp file"),
            std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("warp.csv"), std::string::npos) << e.what();
}

// Under gravity something must hold the fabric up: a node held in z, or a body.
TEST_F(ModelBuilder, GravityWithNothingToHangFromIsRefused) {
  dir.write("table.csv", "areal_density_kg_m2,0.25\nstrain,tension_N_per_m\n0,0\n1,500\n");
  const std::string fabric = "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [4, 4]\n"
                             "warp = \"table.csv\"\nweft = \"table.csv\"\n[gravity]\n";
  const InputError e = error(fabric + "[[constraint]]\nnodes = \"perimeter\"\naxes = \"xy\"\n");
  EXPECT_EQ(e.where().line, 6) << e.what();
  EXPECT_NE(std::string(e.what()).find("nothing to hold the fabric up"), std::string::npos) << e.what();
  EXPECT_TRUE(build(fabric + "[[constraint]]\nnodes = \"corners\"\naxes = \"z\"\n").loaded());
}

// One file stating the density is enough; the other may leave it out.
TEST_F(ModelBuilder, OneFileStatingTheDensityIsEnough) {
  dir.write("weft.csv", "areal_density_kg_m2,0.3\nstrain,tension_N_per_m\n0,0\n1,500\n");
  std::string text = scene("[gravity]\n");
  const std::string weft = "weft = \"table.csv\"";
  text.replace(text.find(weft), weft.size(), "weft = \"weft.csv\"");
  const Model model = build(text);
  ASSERT_NE(test::find_term<Gravity>(model), nullptr);
  EXPECT_NEAR(test::find_term<Gravity>(model)->loads()[0].z(), -0.3 * model.fabric.node_areas()[0] * kStandardGravity_m_s2, 1e-15);
}

}  // namespace
}  // namespace fabform::model_builder_test
