// Bad command-line flags and bad scene values, through the real binary (issue "Reliability",
// item 1): every shorthand flag (--solver, --tol, --tol-m, --max-iter, --threads) and --set with bad
// values, unknown options, missing values, and a scene file with a bad value in each section.
// Each run must fail while reading its input: exit status 2, exactly one line on standard error
// starting "fabform: error:" and naming the key (with the scene file's line when the value is
// in it), and no output folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>

#include "support/cli.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::run_flags_test {
namespace {

using test::Outcome;
using test::run_fabform;

// A valid scene with every section, on the repository's material tables and dome mold.
std::string base_scene() {
  const std::string materials = test::source_path("materials/white-swim-solid_");
  return "[scene]\n"
         "name = \"flags\"\n"
         "[fabric]\n"
         "size_m = [0.1, 0.1]\n"
         "divisions = [4, 4]\n"
         "origin_m = [0.0, 0.0, 0.05]\n"
         "warp = \"" + materials + "warp.csv\"\n"
         "weft = \"" + materials + "weft.csv\"\n"
         "[[body]]\n"
         "mesh = \"" + test::source_path("molds/dome_hemisphere_r30mm.obj") + "\"\n"
         "units = \"mm\"\n"
         "translation_m = [0.05, 0.05, 0.0]\n"
         "[[constraint]]\n"
         "nodes = \"perimeter\"\n"
         "[initial]\n"
         "shape = \"lift\"\n"
         "height_m = 0.01\n"
         "[solver]\n"
         "tolerance_N = 1e-3\n"
         "max_iterations = 1000\n"
         "[output]\n"
         "checkpoint_every_minutes = 10.0\n";
}

class RunFlags : public ::testing::Test {
 protected:
  // Writes the scene with `from` replaced by `to`; returns the line `to` starts on (0 if no edit).
  int write_scene(const std::string& from = "", const std::string& to = "") {
    std::string text = base_scene();
    int line = 0;
    if (!from.empty()) {
      const auto at = text.find(from);
      if (at == std::string::npos) throw std::logic_error("not in the base scene: " + from);
      text.replace(at, from.size(), to);
      line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    }
    dir.write("scene.toml", text);
    return line;
  }
  bool out_exists() const { return std::filesystem::exists(dir.path("out")); }
  test::TempDir dir;
};

// The scene and flags are valid: a run with no iterations writes its results. Without this,
// "no output folder" below could mean nothing.
TEST_F(RunFlags, TheBaseSceneRuns) {
  write_scene();
  const Outcome o = run_fabform(dir, "run scene.toml --out out --max-iter 0 --quiet");
  EXPECT_TRUE(o.status == 0 || o.status == 3) << o.err;
  EXPECT_TRUE(std::filesystem::exists(dir.path("out/result.json"))) << o.err;
}

struct BadFlag {
  const char* name;
  const char* flags;  // after `run scene.toml --out out`, as a shell would read them
  const char* names;  // what the message must name: the scene key, or the flag
};

std::ostream& operator<<(std::ostream& out, const BadFlag& b) { return out << b.name; }

void expect_one_line_error(const Outcome& o, const std::string& names) {
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_EQ(test::error_line_count(o.err), 1) << o.err;
  EXPECT_EQ(o.err.rfind("fabform: error: ", 0), 0u) << o.err;
  EXPECT_NE(o.err.find(names), std::string::npos) << o.err << "does not name " << names;
}

class RunFlagsBadFlag : public RunFlags, public ::testing::WithParamInterface<BadFlag> {};

TEST_P(RunFlagsBadFlag, ExitsTwoWithOneLineNamingItAndWritesNothing) {
  write_scene();
  const Outcome o = run_fabform(dir, std::string("run scene.toml --out out ") + GetParam().flags);
  expect_one_line_error(o, GetParam().names);
  EXPECT_FALSE(out_exists()) << "an output folder was created for bad input";
}

INSTANTIATE_TEST_SUITE_P(
    EveryFlag, RunFlagsBadFlag,
    ::testing::Values(
        // --solver NAME = solver.name
        BadFlag{"SolverUnknown", "--solver simplex", "solver.name: unknown solver 'simplex'"},
        BadFlag{"SolverEmpty", "--solver ''", "solver.name"},
        BadFlag{"SolverNumber", "--solver 3", "solver.name: must be a string"},
        BadFlag{"SolverMissingValue", "--solver", "--solver: needs a value"},
        // --tol N = solver.tolerance_N
        BadFlag{"TolNaN", "--tol nan", "solver.tolerance_N: must be finite"},
        BadFlag{"TolInf", "--tol inf", "solver.tolerance_N: must be finite"},
        BadFlag{"TolNegative", "--tol -1e-3", "solver.tolerance_N"},
        BadFlag{"TolZero", "--tol 0", "solver.tolerance_N"},
        BadFlag{"TolWord", "--tol fast", "solver.tolerance_N: must be a number"},
        BadFlag{"TolBeyondDouble", "--tol 1e999", "solver.tolerance_N: not a usable number"},
        BadFlag{"TolMissingValue", "--tol", "--tol: needs a value"},
        // --tol-m METRES = solver.tolerance_m
        BadFlag{"TolMZero", "--tol-m 0", "solver.tolerance_m: must be a positive, finite distance"},
        BadFlag{"TolMNegative", "--tol-m -1e-4", "solver.tolerance_m: must be a positive, finite distance"},
        BadFlag{"TolMNaN", "--tol-m nan", "solver.tolerance_m: must be finite"},
        BadFlag{"TolMWord", "--tol-m 1mm", "solver.tolerance_m: must be a number"},
        BadFlag{"TolMMissingValue", "--tol-m", "--tol-m: needs a value"},
        BadFlag{"SetTolMZero", "--set solver.tolerance_m=0", "solver.tolerance_m: must be a positive"},
        // --max-iter K = solver.max_iterations
        BadFlag{"MaxIterNegative", "--max-iter -1", "solver.max_iterations: must be between 0 and"},
        BadFlag{"MaxIterFraction", "--max-iter 1.5", "solver.max_iterations: must be an integer"},
        BadFlag{"MaxIterNaN", "--max-iter nan", "solver.max_iterations: must be an integer"},
        BadFlag{"MaxIterBeyondInt", "--max-iter 99999999999", "solver.max_iterations: must be between 0 and"},
        BadFlag{"MaxIterBeyondInt64", "--max-iter 99999999999999999999", "solver.max_iterations: not a usable number"},
        BadFlag{"MaxIterWord", "--max-iter many", "solver.max_iterations: must be an integer"},
        BadFlag{"MaxIterMissingValue", "--max-iter", "--max-iter: needs a value"},
        // --threads T = solver.threads
        BadFlag{"ThreadsZero", "--threads 0", "solver.threads: must be between 1 and 1024"},
        BadFlag{"ThreadsNegative", "--threads -2", "solver.threads: must be between 1 and 1024"},
        BadFlag{"ThreadsTooMany", "--threads 1025", "solver.threads: must be between 1 and 1024"},
        BadFlag{"ThreadsFraction", "--threads 2.5", "solver.threads: must be an integer"},
        BadFlag{"ThreadsNaN", "--threads nan", "solver.threads: must be an integer"},
        BadFlag{"ThreadsMissingValue", "--threads", "--threads: needs a value"},
        // --set KEY=VALUE
        BadFlag{"SetNaN", "--set solver.C=nan", "solver.C: must be finite"},
        BadFlag{"SetNegativeScale", "--set body.0.scale=-1", "body.0.scale: must be positive"},
        BadFlag{"SetZeroSize", "--set fabric.size_m=[0.1,0]", "fabric.size_m: both sides must be positive"},
        BadFlag{"SetHugeRotation", "--set body.0.rotation_deg=[1e300,0,0]", "body.0.rotation_deg"},
        BadFlag{"SetHugeInteger", "--set fabric.divisions=[99999999999,4]", "fabric.divisions: must be between 1 and 10000"},
        BadFlag{"SetWrongTypeWord", "--set fabric.divisions=fine", "fabric.divisions: must be an array of two integers"},
        BadFlag{"SetWrongTypeTable", "--set 'solver.C={value=2}'", "solver.C: must be a number"},
        BadFlag{"SetWrongLength", "--set fabric.size_m=[0.1]", "fabric.size_m: must be an array of 2 numbers"},
        BadFlag{"SetEmptyName", "--set scene.name=", "scene.name: must not be empty"},
        BadFlag{"SetEmptyValue", "--set solver.C=", "solver.C: must be a number"},
        BadFlag{"SetUnknownKey", "--set solver.speed=3", "command line --set: solver.speed: unknown key"},
        BadFlag{"SetUnknownSection", "--set weather.wind=9.81", "command line --set: weather: unknown key"},
        BadFlag{"SetIndexOutOfRange", "--set body.1.scale=2", "body.1.scale: index 1 is out of range"},
        BadFlag{"SetIndexNotDigits", "--set body.0x.scale=2", "body.0x.scale: '0x' must be an array index"},
        BadFlag{"SetInsideAValue", "--set fabric.size_m.0=0.2", "fabric.size_m.0: cannot set a value inside a non-table"},
        BadFlag{"SetKeyWithSpace", "--set 'solver. C=2'", "key parts are bare keys"},
        BadFlag{"SetEmptyKeyPart", "--set solver..C=2", "solver..C: empty part in the dotted key"},
        BadFlag{"SetNoEquals", "--set solver.C", "solver.C: expected KEY=VALUE"},
        BadFlag{"SetMissingValue", "--set", "--set: needs a value"},
        // Options and arguments
        BadFlag{"UnknownOption", "--tolerance 1e-3", "--tolerance: unknown option"},
        BadFlag{"UnknownShortOption", "-q", "-q: unknown option"},
        BadFlag{"SecondScene", "other.toml", "other.toml: only one scene"},
        BadFlag{"ResumeWithAScene", "--resume out", "--resume: takes the scene"}),
    [](const auto& case_info) { return std::string(case_info.param.name); });

// A bad value written in the scene file, one per section, and a TOML error.
struct BadSceneValue {
  const char* name;
  const char* from;  // a line of the base scene
  const char* to;
  const char* key;  // the dotted key the message names, after "scene.toml:LINE: "
};

std::ostream& operator<<(std::ostream& out, const BadSceneValue& b) { return out << b.name; }

class RunFlagsBadScene : public RunFlags, public ::testing::WithParamInterface<BadSceneValue> {};

TEST_P(RunFlagsBadScene, ExitsTwoNamingFileLineAndKeyAndWritesNothing) {
  const BadSceneValue& bad = GetParam();
  const int line = write_scene(bad.from, bad.to);
  const Outcome o = run_fabform(dir, "run scene.toml --out out");
  expect_one_line_error(o, "scene.toml:" + std::to_string(line) + ": " + bad.key + ": ");
  EXPECT_FALSE(out_exists()) << "an output folder was created for bad input";
}

INSTANTIATE_TEST_SUITE_P(
    EverySection, RunFlagsBadScene,
    ::testing::Values(
        BadSceneValue{"SceneNameLeavesResults", "name = \"flags\"", "name = \"../flags\"", "scene.name"},
        BadSceneValue{"FabricZeroDivisions", "divisions = [4, 4]", "divisions = [0, 4]", "fabric.divisions"},
        BadSceneValue{"FabricNaNSize", "size_m = [0.1, 0.1]", "size_m = [nan, 0.1]", "fabric.size_m"},
        BadSceneValue{"BodyUnknownUnit", "units = \"mm\"", "units = \"furlong\"", "body.0.units"},
        BadSceneValue{"BodyTableForAVector", "translation_m = [0.05, 0.05, 0.0]", "translation_m = { x = 0.05 }",
                      "body.0.translation_m"},
        BadSceneValue{"ConstraintUnknownSet", "nodes = \"perimeter\"", "nodes = \"rim\"", "constraint.0.nodes"},
        BadSceneValue{"ConstraintPointOffTheFabric", "nodes = \"perimeter\"", "nearest_m = [-0.05, 0.05]",
                      "constraint.0.nearest_m"},
        BadSceneValue{"InitialNaNHeight", "height_m = 0.01", "height_m = nan", "initial.height_m"},
        BadSceneValue{"InitialZeroHeight", "height_m = 0.01", "height_m = 0.0", "initial.height_m"},
        BadSceneValue{"SolverTableForANumber", "tolerance_N = 1e-3", "tolerance_N = { value = 1e-3 }",
                      "solver.tolerance_N"},
        BadSceneValue{"SolverBeyondInt64", "max_iterations = 1000", "max_iterations = 99999999999999999999",
                      "solver.max_iterations"},
        BadSceneValue{"OutputNegativeMinutes", "checkpoint_every_minutes = 10.0", "checkpoint_every_minutes = -1.0",
                      "output.checkpoint_every_minutes"},
        BadSceneValue{"OutputEmptyDir", "checkpoint_every_minutes = 10.0", "dir = \"\"", "output.dir"}),
    [](const auto& case_info) { return std::string(case_info.param.name); });

}  // namespace
}  // namespace fabform::run_flags_test
