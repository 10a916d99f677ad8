// The command-line contract, exercised on the real binary: exit statuses, one-line
// errors that name the file, and output folders that are complete or untouched.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>

#include "fabform/io/obj_text.hpp"
#include "fabform/scene/memory_budget.hpp"
#include "support/cli.hpp"
#include "support/shapes.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::run_command_test {
namespace {

using test::line_count;
using test::Outcome;
using test::slurp;

using test::run_fabform;

// A small scene whose answer takes a moment: a clamped, pre-lifted square over a sphere.
class RunCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("table.csv", "# linear test table\nstrain,tension_N_per_m\n0,0\n1,500\n");
    dir.write("sphere.obj", obj_text(test::uv_sphere({0.05, 0.05, -0.02}, 0.03, 20, 40)));
    dir.write("scene.toml",
              "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [10, 10]\n"
              "warp = \"table.csv\"\nweft = \"table.csv\"\n"
              "[[body]]\nmesh = \"sphere.obj\"\nunits = \"m\"\n"
              "[[constraint]]\nnodes = \"perimeter\"\n"
              "[initial]\nshape = \"lift\"\nheight_m = 0.02\n"
              "[solver]\ntolerance_N = 1e-5\n");
  }
  bool exists(const std::string& name) const { return std::filesystem::exists(dir.path(name)); }
  // Bad input: exit status 2, one line saying what is wrong, no output folder.
  void expect_refused(const Outcome& o, const std::string& expected_in_message) const {
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_EQ(test::error_line_count(o.err), 1) << o.err;
    EXPECT_NE(o.err.find(expected_in_message), std::string::npos) << o.err;
    EXPECT_FALSE(exists("out")) << "an output folder was created for bad input";
  }
  test::TempDir dir;
};

TEST_F(RunCommand, ConvergedRunWritesEveryResult) {
  const Outcome o = run_fabform(dir, "run scene.toml --out out");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.err.find("results in out"), std::string::npos) << o.err;
  const std::string json = slurp(dir.path("out/result.json"));
  for (const char* key : {"\"converged\": true", "\"termination\": \"converged\"", "\"iterations\"",
                          "\"residual_N\"", "\"wall_seconds\"", "\"solver\": \"relax\"",
                          "\"nodes\": 121", "\"contact_nodes\"", "\"max_penetration_m\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << " missing from\n" << json;
  const std::string csv = slurp(dir.path("out/convergence.csv"));
  EXPECT_EQ(csv.rfind("iteration,residual_N,seconds", 0), 0u) << csv.substr(0, 80);
  EXPECT_GT(line_count(csv), 2);
  EXPECT_EQ(line_count(slurp(dir.path("out/fabric.obj"))), 1 + 121 + 100);
  const std::string vtk = slurp(dir.path("out/fabric.vtk"));
  for (const char* field : {"strain_warp", "strain_weft", "contact", "residual_N", "POINT_DATA 121"})
    EXPECT_NE(vtk.find(field), std::string::npos) << field;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path("out")))
    EXPECT_NE(entry.path().extension(), ".tmp") << "left a temporary file: " << entry.path();
}

// What a reader skipped in a body's file is among the run's warnings, as check prints it.
TEST_F(RunCommand, WhatTheMeshReaderSkippedIsWarned) {
  dir.write("sphere.obj", slurp(dir.path("sphere.obj")) + "l 1 2\n");
  const Outcome o = run_fabform(dir, "run scene.toml --out out --quiet");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(slurp(dir.path("out/result.json")).find("sphere.obj: skipped 1 point, line or face"), std::string::npos);
}

TEST_F(RunCommand, IterationCapExitsThreeAndSaysSo) {
  const Outcome o = run_fabform(dir, "run scene.toml --out out --max-iter 2 --tol 1e-9");
  EXPECT_EQ(o.status, 3) << o.err;
  const std::string json = slurp(dir.path("out/result.json"));
  EXPECT_NE(json.find("\"converged\": false"), std::string::npos);
  EXPECT_NE(json.find("\"termination\": \"not converged\""), std::string::npos);
  EXPECT_EQ(line_count(slurp(dir.path("out/convergence.csv"))), 1 + 3);
}

TEST_F(RunCommand, SetOverridesAnySceneValue) {
  const Outcome o = run_fabform(dir, "run scene.toml --out out --set fabric.divisions=[6,6]");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(slurp(dir.path("out/result.json")).find("\"nodes\": 49"), std::string::npos);
}

// A body with a triangle facing the wrong way is refused by run as check refuses it: one
// verdict, in the same words, naming the mesh file (contact near such a triangle would take
// outside for inside). Nothing is written.
TEST_F(RunCommand, BodyWithAFlippedTriangleIsRefusedAsCheckRefusesIt) {
  TriangleMesh sphere = test::uv_sphere({0.05, 0.05, -0.02}, 0.03, 20, 40);
  test::flip(&sphere.triangles.back());  // at the south pole
  dir.write("sphere.obj", obj_text(sphere));
  const Outcome run = run_fabform(dir, "run scene.toml --out out");
  EXPECT_EQ(run.status, 2) << run.err;
  const std::string refusal = run.err.substr(run.err.find("fabform: error: "));
  EXPECT_EQ(line_count(refusal), 1) << run.err;
  EXPECT_NE(refusal.find("sphere.obj: inconsistent orientation: 3 edges"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("--repair"), std::string::npos) << refusal;
  EXPECT_FALSE(std::filesystem::exists(dir.path("out")));
  const Outcome check = run_fabform(dir, "check sphere.obj");
  EXPECT_EQ(check.status, 2);
  EXPECT_EQ(check.err, "fabform: error: sphere.obj" + refusal.substr(refusal.find(": inconsistent")));
}

// The refusal comes before any solve: with a coarser grid to solve first, that grid is not
// solved (it could take long on a large fabric), and the error is the only line.
TEST_F(RunCommand, BodyIsRefusedBeforeTheCoarserGridsAreSolved) {
  TriangleMesh sphere = test::uv_sphere({0.05, 0.05, -0.02}, 0.03, 20, 40);
  test::flip(&sphere.triangles.back());
  dir.write("sphere.obj", obj_text(sphere));
  const Outcome run = run_fabform(dir, "run scene.toml --out out --solver newton --set fabric.divisions=[40,40] "
                                       "--set solver.continuation_levels=1");
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_EQ(run.err.find("continuation grid"), std::string::npos) << run.err;
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("sphere.obj: inconsistent orientation"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path("out")));
}

// Bad input: exit status 2, one line naming the file (and line), nothing written.
struct BadRun {
  const char* name;
  const char* arguments;
  const char* file_to_write;  // "" for none
  const char* content;
  const char* expected_in_message;
};

class RunCommandBadInput : public RunCommand, public ::testing::WithParamInterface<BadRun> {};

TEST_P(RunCommandBadInput, ExitsTwoWithOneLineAndWritesNothing) {
  const BadRun& bad = GetParam();
  if (std::string(bad.file_to_write).size() > 0) dir.write(bad.file_to_write, bad.content);
  const Outcome o = run_fabform(dir, bad.arguments);
  expect_refused(o, bad.expected_in_message);
}

INSTANTIATE_TEST_SUITE_P(
    Contract, RunCommandBadInput,
    ::testing::Values(
        BadRun{"MissingScene", "run nowhere.toml --out out", "", "", "nowhere.toml: no such scene file"},
        BadRun{"DecreasingTable", "run scene.toml --out out", "table.csv",
               "strain,tension_N_per_m\n0,0\n0.5,10\n0.4,20\n", "table.csv:4:"},
        BadRun{"EmptyMesh", "run scene.toml --out out", "sphere.obj", "", "sphere.obj"},
        BadRun{"UnknownKey", "run scene.toml --out out --set solver.speed=3", "", "", "solver.speed: unknown key"},
        BadRun{"BadTolerance", "run scene.toml --out out --tol fast", "", "", "solver.tolerance_N"},
        BadRun{"UnknownOption", "run scene.toml --out out --fast", "", "", "--fast: unknown option"},
        BadRun{"MissingValue", "run scene.toml --out", "", "", "--out: needs a value"},
        BadRun{"FallingTable", "run scene.toml --out out", "table.csv",
               "strain,tension_N_per_m\n0,0\n0.5,10\n0.8,5\n", "table.csv:4: the tension falls with strain"},
        BadRun{"OutputIsAFile", "run scene.toml --out table.csv", "", "", "table.csv: is a file"},
        BadRun{"StartsInside", "run scene.toml --out out --set initial.height_m=0.005", "", "",
               "starts inside body"}),
    [](const auto& case_info) { return std::string(case_info.param.name); });

// Bad drape scenes (issue 5): the shipped pin and Cusick scenes with one value made wrong.
struct BadDrape {
  const char* name;
  const char* scene;      // scenes/NAME.toml
  const char* overrides;  // --set arguments
  const char* expected_in_message;
};

class RunCommandBadDrape : public RunCommand, public ::testing::WithParamInterface<BadDrape> {};

TEST_P(RunCommandBadDrape, ExitsTwoWithOneLineAndWritesNothing) {
  const BadDrape& bad = GetParam();
  // A table that does not say what the fabric weighs.
  dir.write("weightless.csv", "strain,tension_N_per_m\n0,0\n1,500\n");
  const std::string scene = test::source_path(std::string("scenes/") + bad.scene + ".toml");
  std::string overrides = bad.overrides;
  for (auto at = overrides.find("WEIGHTLESS"); at != std::string::npos; at = overrides.find("WEIGHTLESS"))
    overrides.replace(at, 10, dir.path("weightless.csv"));
  const Outcome o = run_fabform(dir, "run " + scene + " --out out " + overrides);
  expect_refused(o, bad.expected_in_message);
}

INSTANTIATE_TEST_SUITE_P(
    Contract, RunCommandBadDrape,
    ::testing::Values(
        BadDrape{"CircleSmallerThanTheDisc", "cusick",
                 "--set fabric.diameter_m=0.15 --set fabric.origin_m=[-0.075,-0.075,0.0005] "
                 "--set drape.clamp_radius_m=0.05",
                 "the 0.15 m circle does not cover body 'disc'"},
        BadDrape{"ClampAsWideAsTheSpecimen", "cusick", "--set drape.clamp_radius_m=0.15",
                 "drape.clamp_radius_m: is 0.15 m, not smaller than the specimen's radius 0.15 m"},
        BadDrape{"BendingLengthOfZero", "cusick", "--unset bending.rigidity_uNm --set bending.bending_length_cm=0",
                 "bending.bending_length_cm: must be in (0, 1000] cm"},
        BadDrape{"MassThatIsNotTheTables", "cusick", "--set fabric.areal_mass_g_m2=192",
                 "fabric.areal_mass_g_m2: 192 g/m² differs from the material file's 204 g/m²"},
        BadDrape{"UnsetOfNoKey", "cusick", "--unset bending.rigidity_Nm", "bending.rigidity_Nm: --unset: the scene has no such key"},
        BadDrape{"CircleOffTheDisc", "cusick", "--set fabric.origin_m=[0.0,0.0,0.002]", "does not cover body 'disc'"},
        BadDrape{"PinOutsideTheFabric", "pin", "--set constraint.0.nearest_m=[0.29,0.29]",
                 "--set: constraint.0.nearest_m: must lie on the fabric: within 0.15 m of its centre"},
        BadDrape{"SupportThatIsNoBody", "cusick", "--set 'drape.support=\"table\"'", "no body named 'table'"},
        BadDrape{"NoDensityWithGravity", "pin",
                 "--set 'fabric.warp=\"WEIGHTLESS\"' --set 'fabric.weft=\"WEIGHTLESS\"'",
                 "gravity needs the fabric's mass per area"},
        BadDrape{"WindWithoutADirection", "pin", "--solver dynamic --set wind.coefficient_N_s_m3=1",
                 "wind.velocity_m_s: wind without a direction"},
        BadDrape{"WindStill", "pin", "--solver dynamic --set wind.velocity_m_s=[0,0,0] --set wind.coefficient_N_s_m3=1",
                 "wind.velocity_m_s: wind without a direction: the velocity is zero"},
        BadDrape{"WindForNewton", "cusick", "--set wind.velocity_m_s=[1,0,0] --set wind.coefficient_N_s_m3=1",
                 "only solver dynamic models it, not newton"},
        BadDrape{"PathWithoutSteps", "cup", "--set body.0.path.steps=0",
                 "body.0.path.steps: must be between 1 and 100000"},
        BadDrape{"HolderForceBelowZero", "cup", "--set clamp.force_N=-5", "clamp.force_N: must be in [0, 1e6] N"},
        BadDrape{"HolderForDynamic", "cup", "--solver dynamic", "whose friction only newton models, not dynamic"},
        BadDrape{"PressureNotFinite", "cup", "--set pressure.pressure_Pa=nan", "pressure.pressure_Pa"},
        BadDrape{"NewtonInTheWindOverridden", "pin",
                 "--solver newton --set wind.velocity_m_s=[1,0,0] --set wind.coefficient_N_s_m3=1",
                 "command line --set: solver.name: the scene has wind"}),
    [](const auto& case_info) { return std::string(case_info.param.name); });

TEST_F(RunCommand, TriangularMeshWithoutAShearTableIsRefused) {
  dir.write("linear.csv", "strain,tension_N_per_m\n0,0\n1,500\n");
  dir.write("tri.toml", "[fabric]\nshape = \"circle\"\ndiameter_m = 0.3\nmesh = \"triangular\"\ndivisions = 8\n"
                        "warp = \"linear.csv\"\nweft = \"linear.csv\"\n[[constraint]]\nnodes = \"perimeter\"\n");
  expect_refused(run_fabform(dir, "run tri.toml --out out"), "a triangular mesh has diagonal springs");
}

// Seed 004's wind on a clamped square: dynamic brings it to rest bulging downwind, and the
// report says the wind was modelled.
TEST_F(RunCommand, WindBlowsAClampedSquareDownwind) {
  dir.write("linear.csv", "strain,tension_N_per_m\n0,0\n1,500\n");
  dir.write("wind.toml",
            "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [6, 6]\nwarp = \"linear.csv\"\nweft = \"linear.csv\"\n"
            "[[constraint]]\nnodes = \"perimeter\"\n[wind]\nvelocity_m_s = [0.0, 3.0, -4.0]\ncoefficient_N_s_m3 = 1.0\n"
            "[initial]\nshape = \"flat\"\n[solver]\nname = \"dynamic\"\ntolerance_N = 1e-8\nmax_iterations = 1000000\n");
  const Outcome o = run_fabform(dir, "run wind.toml --out out");
  ASSERT_EQ(o.status, 0) << o.err;
  const std::string json = slurp(dir.path("out/result.json"));
  EXPECT_NE(json.find("wind: seed 004's C·A·[n·(v_wind − v)]·n on each node, v_wind = (0, 3, -4) m/s, C = 1 N·s/m³"),
            std::string::npos)
      << json;
  double lowest = 0.0;
  std::istringstream obj(slurp(dir.path("out/fabric.obj")));
  for (std::string tag; obj >> tag;) {
    if (tag != "v") continue;
    double x = 0, y = 0, z = 0;
    obj >> x >> y >> z;
    lowest = std::min(lowest, z);
  }
  EXPECT_LT(lowest, -1e-3) << "the wind blows along -z across the square";
}

// Tensions near the largest double on springs 5 m wide overflow at the start: the run stops as
// a numerical failure naming the node and iteration, exits 4, and still writes its results.
TEST_F(RunCommand, OverflowIsANumericalFailureWithItsResultsWritten) {
  dir.write("huge.csv", "strain,tension_N_per_m\n0,0\n1,1e308\n");
  dir.write("huge.toml",
            "[fabric]\nsize_m = [10, 10]\ndivisions = [2, 2]\nwarp = \"huge.csv\"\nweft = \"huge.csv\"\n"
            "[[constraint]]\nnodes = \"perimeter\"\n[initial]\nshape = \"bump\"\nheight_m = 5\n");
  const Outcome o = run_fabform(dir, "run huge.toml --out out");
  EXPECT_EQ(o.status, 4) << o.err;
  const std::string json = slurp(dir.path("out/result.json"));
  EXPECT_NE(json.find("\"termination\": \"numerical failure\""), std::string::npos) << json;
  EXPECT_NE(json.find("NaN or Inf at node 4 in iteration 0"), std::string::npos) << json;
  EXPECT_NE(json.find("\"residual_N\": null"), std::string::npos) << json;
  EXPECT_EQ(line_count(slurp(dir.path("out/fabric.obj"))), 1 + 9 + 4);
  EXPECT_FALSE(exists("out/checkpoint.bin")) << "a broken run is not to be resumed";
}

TEST_F(RunCommand, BadInputLeavesAnExistingFolderUntouched) {
  ASSERT_EQ(run_fabform(dir, "run scene.toml --out out").status, 0);
  const std::string before = slurp(dir.path("out/result.json"));
  dir.write("table.csv", "strain,tension_N_per_m\n0,0\n");
  EXPECT_EQ(run_fabform(dir, "run scene.toml --out out").status, 2);
  EXPECT_EQ(slurp(dir.path("out/result.json")), before);
}

// 49 million nodes need at least 36.8 GB with relax: refused before anything is allocated.
TEST_F(RunCommand, GridLargerThanMemoryIsRefusedWithTheEstimate) {
  if (available_memory_bytes() > 36.8e9) GTEST_SKIP() << "this machine could hold the grid";
  expect_refused(run_fabform(dir, "run scene.toml --out out --set fabric.divisions=[7000,7000]"),
                 "--set: fabric.divisions: a fabric of 4.9e+07 nodes needs at least 36.8 GB with solver relax");
}

// Without a shear table that stiffens, the scene says where a cell locks.
TEST_F(RunCommand, TheScenesLockingAngleJudgesTheShear) {
  const Outcome scene_value = run_fabform(dir, "run scene.toml --out out --quiet --set fabric.locking_angle_deg=0.01");
  ASSERT_EQ(scene_value.status, 0) << scene_value.err;
  const std::string json = slurp(dir.path("out/result.json"));
  EXPECT_NE(json.find("\"locking_angle_from\": \"scene\""), std::string::npos);
  EXPECT_NE(json.find("\"locking_angle_deg\": 0.01"), std::string::npos);
  const std::size_t at = json.find("\"wrinkle_cells\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GT(std::stoi(json.substr(at + 17)), 0) << "a fabric over a sphere shears by more than 0.01 degrees";
  ASSERT_EQ(run_fabform(dir, "run scene.toml --out out --quiet").status, 0);
  EXPECT_NE(slurp(dir.path("out/result.json")).find("\"locking_angle_from\": \"default\""), std::string::npos);
}

TEST_F(RunCommand, FallingTableMeantToSoftenRuns) {
  dir.write("table.csv", "strain,tension_N_per_m\n0,0\n0.5,250\n2,200\n");
  const Outcome o = run_fabform(dir, "run scene.toml --out out --set fabric.softening=true");
  EXPECT_EQ(o.status, 0) << o.err;
}

// Runs `fabform ARGUMENTS` in dir with a 64 kB tmpfs mounted at dir/small, in a mount namespace of
// its own that vanishes with the process; nullopt where the system refuses namespaces (not root).
std::optional<Outcome> run_with_small_disk(const test::TempDir& dir, const std::string& arguments) {
  if (std::system("unshare -m true 2>/dev/null") != 0) return std::nullopt;
  std::filesystem::create_directories(dir.path("small"));
  const std::string command = "cd '" + dir.root().string() + "' && unshare -m sh -c 'mount -t tmpfs -o size=64k none small && " +
                              test::fabform_binary() + " " + arguments + "' >stdout.txt 2>stderr.txt";
  const int raw = std::system(command.c_str());
  return Outcome{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir.path("stdout.txt")), slurp(dir.path("stderr.txt"))};
}

// A mount point cannot be renamed into: found by the probe before the solve, not after it.
TEST_F(RunCommand, OutputOnAMountPointIsRefusedBeforeTheSolve) {
  const auto o = run_with_small_disk(dir, "run scene.toml --out small");
  if (!o) GTEST_SKIP() << "mount namespaces need root";
  EXPECT_EQ(o->status, 2) << o->err;
  EXPECT_NE(o->err.find("small: the output folder cannot take results"), std::string::npos) << o->err;
  EXPECT_EQ(o->err.find("fabform: scene"), std::string::npos) << "the solve started: " << o->err;
}

// The results outgrow a full disk: the system's reason, its own exit status, nothing half-written.
TEST_F(RunCommand, FullDiskSaysSoAndExitsFive) {
  const auto o = run_with_small_disk(dir, "run scene.toml --out small/out --set fabric.divisions=[60,60] --max-iter 2 --quiet");
  if (!o) GTEST_SKIP() << "mount namespaces need root";
  EXPECT_EQ(o->status, 5) << o->err;
  EXPECT_NE(o->err.find("No space left on device"), std::string::npos) << o->err;
  EXPECT_NE(o->err.find("keeps what it held"), std::string::npos) << o->err;
}

TEST(Cli, SolversListsEverySolver) {
  test::TempDir dir;
  const Outcome o = run_fabform(dir, "solvers");
  EXPECT_EQ(o.status, 0);
  EXPECT_EQ(o.out, "relax\ndynamic\nnewton\n");
}

TEST(Cli, UnknownCommandIsAUsageError) {
  test::TempDir dir;
  EXPECT_EQ(run_fabform(dir, "frobnicate").status, 2);
  EXPECT_EQ(run_fabform(dir, "").status, 2);
}

}  // namespace
}  // namespace fabform::run_command_test
