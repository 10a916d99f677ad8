// Scene files: what they mean once read, and how a bad one is reported (file, line, key).
#include "fabform/scene/scene_toml.hpp"

#include <gtest/gtest.h>

#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::scene_toml_test {
namespace {

// A minimal valid scene; tests append or replace lines to break it.
const char* kMinimal =
    "[fabric]\n"                          // line 1
    "size_m = [0.1, 0.2]\n"               // line 2
    "divisions = [4, 8]\n"                // line 3
    "warp = \"warp.csv\"\n"               // line 4
    "weft = \"weft.csv\"\n"               // line 5
    "[[constraint]]\n"                    // line 6
    "nodes = \"perimeter\"\n"             // line 7
    "[solver]\n"                          // line 8
    "tolerance_N = 1e-3\n";               // line 9

InputError load_error(const std::string& text, const std::vector<SceneOverride>& overrides = {}) {
  test::TempDir dir;
  const std::string path = dir.write("scene.toml", text);
  try {
    load_scene(path, overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError({}, "");
}

TEST(LoadScene, ReadsValuesInSIAndResolvesPaths) {
  test::TempDir dir;
  const std::string path = dir.write("scene.toml", kMinimal);
  const Scene scene = load_scene(path);
  EXPECT_EQ(scene.name, "scene");
  EXPECT_EQ(scene.fabric.width_m, 0.1);
  EXPECT_EQ(scene.fabric.divisions_weft, 8);
  EXPECT_EQ(scene.warp_path, dir.path("warp.csv"));
  ASSERT_EQ(scene.constraints.size(), 1u);
  EXPECT_EQ(scene.constraints[0].axes, kLockX | kLockY | kLockZ);
  EXPECT_EQ(scene.solver.relax.tolerance_N, 1e-3);
  EXPECT_EQ(scene.solver.name, "relax");
  EXPECT_EQ(scene.initial.kind, InitialShape::Kind::flat);
}

// The dynamic solver's keys reach its options; tolerance and cap are every solver's.
TEST(LoadScene, ReadsTheDynamicSolversKeys) {
  std::string text = kMinimal;
  text.replace(text.find("tolerance_N = 1e-3"), 18,
               "name = \"dynamic\"\ntolerance_N = 2e-4\nmax_iterations = 77\n"
               "areal_density_kg_m2 = 0.15\ndamping = 0.03\n"
               "time_step_fraction = 0.5\nstretch_limit = 0.1");
  test::TempDir dir;
  const Scene scene = load_scene(dir.write("scene.toml", text));
  const DynamicOptions& d = scene.solver.dynamic;
  EXPECT_EQ(scene.solver.name, "dynamic");
  EXPECT_EQ(scene.solver.tolerance_N(), 2e-4);
  EXPECT_EQ(d.max_iterations, 77);
  EXPECT_EQ(d.areal_density_kg_m2, 0.15);
  ASSERT_TRUE(d.damping.has_value());
  EXPECT_EQ(*d.damping, 0.03);
  EXPECT_EQ(d.time_step_fraction, 0.5);
  EXPECT_EQ(d.stretch_limit, 0.1);
  EXPECT_FALSE(load_scene(dir.write("plain.toml", kMinimal)).solver.dynamic.damping.has_value());
}

TEST(LoadScene, ShippedScenesLoad) {
  for (const char* file : {"scenes/mold.toml", "scenes/torso.toml", "scenes/torso_frictionless.toml",
                           "scenes/vacuum.toml", "scenes/cup.toml"}) {
    const Scene scene = load_scene(test::source_path(file));
    EXPECT_FALSE(scene.bodies.empty()) << file;
    EXPECT_TRUE(!scene.constraints.empty() || scene.clamp.on) << file << ": nothing holds the fabric";
  }
}

TEST(LoadScene, UnknownKeyNamesFileLineAndKey) {
  const InputError e = load_error(std::string(kMinimal) + "toleranse = 3\n");
  EXPECT_EQ(e.where().line, 10);
  EXPECT_EQ(e.where().key, "solver.toleranse");
  EXPECT_NE(std::string(e.what()).find("scene.toml:10: solver.toleranse: unknown key"), std::string::npos)
      << e.what();
}

TEST(LoadScene, UnknownTopLevelTable) {
  const InputError e = load_error(std::string(kMinimal) + "[weather]\nwind = 9.81\n");
  EXPECT_EQ(e.where().key, "weather");
  EXPECT_EQ(e.where().line, 10);
}

TEST(LoadScene, TomlSyntaxErrorNamesTheLine) {
  const InputError e = load_error(std::string(kMinimal) + "max_iterations = = 3\n");
  EXPECT_EQ(e.where().line, 10);
}

TEST(LoadScene, MissingFile) {
  try {
    load_scene("/nonexistent/scene.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "/nonexistent/scene.toml");
  }
}

// Each bad value: the replacement line, the key the message must name, and its line.
struct BadValue {
  const char* from;
  const char* to;
  const char* key;
  int line;
};

class LoadSceneBadValue : public ::testing::TestWithParam<BadValue> {};

TEST_P(LoadSceneBadValue, NamesTheKeyAndLine) {
  std::string text = kMinimal;
  const BadValue& bad = GetParam();
  text.replace(text.find(bad.from), std::string(bad.from).size(), bad.to);
  const InputError e = load_error(text);
  EXPECT_EQ(e.where().key, bad.key) << e.what();
  EXPECT_EQ(e.where().line, bad.line) << e.what();
}

INSTANTIATE_TEST_SUITE_P(
    Sweep, LoadSceneBadValue,
    ::testing::Values(BadValue{"size_m = [0.1, 0.2]", "size_m = [0.1, -0.2]", "fabric.size_m", 2},
                      BadValue{"size_m = [0.1, 0.2]", "size_m = [0.1, nan]", "fabric.size_m", 2},
                      BadValue{"size_m = [0.1, 0.2]", "size_m = \"big\"", "fabric.size_m", 2},
                      BadValue{"size_m = [0.1, 0.2]", "size_m = [0.1]", "fabric.size_m", 2},
                      BadValue{"divisions = [4, 8]", "divisions = [0, 8]", "fabric.divisions", 3},
                      BadValue{"divisions = [4, 8]", "divisions = [4.5, 8]", "fabric.divisions", 3},
                      BadValue{"divisions = [4, 8]", "divisions = [100000, 100000]", "fabric.divisions", 3},
                      BadValue{"warp = \"warp.csv\"", "warp = 3", "fabric.warp", 4},
                      BadValue{"nodes = \"perimeter\"", "nodes = \"rim\"", "constraint.0.nodes", 7},
                      BadValue{"nodes = \"perimeter\"", "nodes = \"perimeter\"\naxes = \"xx\"",
                               "constraint.0.axes", 8},
                      BadValue{"tolerance_N = 1e-3", "tolerance_N = -1", "solver.tolerance_N", 9},
                      BadValue{"tolerance_N = 1e-3", "tolerance_N = inf", "solver.tolerance_N", 9},
                      BadValue{"tolerance_N = 1e-3", "C = 1.0", "solver.C", 9},
                      BadValue{"tolerance_N = 1e-3", "name = \"simplex\"", "solver.name", 9},
                      BadValue{"tolerance_N = 1e-3", "max_iterations = -5", "solver.max_iterations", 9},
                      BadValue{"tolerance_N = 1e-3", "threads = 0", "solver.threads", 9},
                      BadValue{"tolerance_N = 1e-3", "damping = 1.0", "solver.damping", 9},
                      BadValue{"tolerance_N = 1e-3", "areal_density_kg_m2 = 0", "solver.areal_density_kg_m2", 9},
                      BadValue{"tolerance_N = 1e-3", "time_step_fraction = 2", "solver.time_step_fraction", 9},
                      BadValue{"tolerance_N = 1e-3", "stretch_limit = -0.1", "solver.stretch_limit", 9}),
    [](const auto& case_info) {
      std::string name = std::string(case_info.param.key) + "_" + std::to_string(case_info.index);
      for (char& c : name)
        if (c == '.') c = '_';
      return name;
    });

// e relative to the fabric's force scale, or in newtons: one of the two; a command line giving
// the other replaces the scene's.
TEST(LoadScene, ToleranceIsInNewtonsOrRelativeNotBoth) {
  std::string text = kMinimal;
  text.replace(text.find("tolerance_N = 1e-3"), 18, "tolerance_relative = 1e-3");
  test::TempDir dir;
  EXPECT_EQ(load_scene(dir.write("relative.toml", text)).solver.tolerance_relative, 1e-3);
  const Scene newtons = load_scene(dir.write("relative.toml", text), {{"solver.tolerance_N", "2e-4"}});
  EXPECT_EQ(newtons.solver.tolerance_relative, 0.0);
  EXPECT_EQ(newtons.solver.tolerance_N(), 2e-4);
  EXPECT_EQ(load_scene(dir.write("plain.toml", kMinimal), {{"solver.tolerance_relative", "5e-3"}}).solver.tolerance_relative,
            5e-3);
  InputError e = load_error(text + "tolerance_N = 1e-3\n");
  EXPECT_EQ(e.where().key, "solver.tolerance_relative") << e.what();
  EXPECT_NE(std::string(e.what()).find("not both"), std::string::npos) << e.what();
  for (const char* bad : {"0", "-1e-3", "1.5"}) {
    std::string out_of_range = text;
    out_of_range.replace(out_of_range.find("1e-3"), 4, bad);
    e = load_error(out_of_range);
    EXPECT_EQ(e.where().key, "solver.tolerance_relative") << bad;
    EXPECT_EQ(e.where().line, 9) << bad;
  }
}

// A body that keeps the springs out along their length: a penalty only newton carries, named by
// its key and line when another solver is asked for.
TEST(LoadScene, SpringContactIsReadAndNeedsNewton) {
  const std::string body = "[[body]]\nname = \"part\"\nmesh = \"part.obj\"\nunits = \"m\"\nspring_contact = true\n";
  std::string text = kMinimal;
  text.replace(text.find("[solver]\n"), 9, body + "[solver]\nname = \"newton\"\n");
  test::TempDir dir;
  const Scene scene = load_scene(dir.write("scene.toml", text));
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_TRUE(scene.bodies[0].spring_contact);
  EXPECT_EQ(scene.bodies[0].spring_contact_where.line, 12);
  text.replace(text.find("name = \"newton\""), 15, "name = \"relax\"");
  const InputError e = load_error(text);
  EXPECT_EQ(e.where().key, "solver.name") << e.what();
  EXPECT_NE(std::string(e.what()).find("body 'part' keeps springs out along their length (line 12), a penalty only newton carries"),
            std::string::npos) << e.what();
}

// A blank holder gripping a frame round the edge: its width, force and friction, held for newton.
TEST(LoadScene, ReadsAClampFrame) {
  std::string text = kMinimal;
  text.replace(text.find("[solver]\n"), 9, "[clamp]\nwidth_m = 0.02\nforce_N = 40\nfriction = 0.3\n[solver]\nname = \"newton\"\n");
  test::TempDir dir;
  const Scene scene = load_scene(dir.write("scene.toml", text));
  ASSERT_TRUE(scene.clamp.on);
  EXPECT_EQ(scene.clamp.nodes.kind, NodeSetSpec::Kind::frame);
  EXPECT_EQ(scene.clamp.nodes.width_m, 0.02);
  EXPECT_EQ(scene.clamp.force_N, 40.0);
  EXPECT_EQ(scene.clamp.friction, 0.3);
}

TEST(LoadScene, AClampFrameIsOneRegion) {
  std::string text = kMinimal;
  text.replace(text.find("[solver]\n"), 9,
               "[clamp]\nwidth_m = -0.02\nforce_N = 40\nfriction = 0.3\n[solver]\nname = \"newton\"\n");
  InputError e = load_error(text);
  EXPECT_EQ(e.where().key, "clamp.width_m") << e.what();
  EXPECT_EQ(e.where().line, 9) << e.what();
  text.replace(text.find("width_m = -0.02"), 15, "width_m = 0.02\nnodes = \"perimeter\"");
  e = load_error(text);
  EXPECT_EQ(e.where().key, "clamp") << e.what();
  EXPECT_NE(std::string(e.what()).find("not both"), std::string::npos) << e.what();
}

// A syntax error inside a body's path names the key with the body's index.
TEST(LoadScene, SyntaxErrorInABodysPathNamesItsIndex) {
  const std::string text = std::string(kMinimal) +
                           "[[body]]\nmesh = \"a.obj\"\nunits = \"mm\"\n[[body]]\nmesh = \"b.obj\"\nunits = \"mm\"\n"
                           "[body.path]\nsteps = 99999999999999999999\n";
  const InputError e = load_error(text);
  EXPECT_EQ(e.where().key, "body.1.path.steps") << e.what();
  EXPECT_EQ(e.where().line, 17) << e.what();
}

TEST(LoadScene, TravellingBodiesShareTheirSteps) {
  const std::string text = std::string(kMinimal) +
                           "[[body]]\nmesh = \"a.obj\"\nunits = \"mm\"\n[body.path]\nsteps = 4\ntranslation_m = [0, 0, 0.01]\n"
                           "[[body]]\nmesh = \"b.obj\"\nunits = \"mm\"\n[body.path]\nsteps = 5\nrotation_deg = [0, 0, 30]\n";
  const InputError e = load_error(text);
  EXPECT_EQ(e.where().key, "body.1.path.steps") << e.what();
  EXPECT_NE(std::string(e.what()).find("same steps"), std::string::npos) << e.what();
}

TEST(LoadScene, MissingRequiredKeyNamesIt) {
  std::string text = kMinimal;
  text.replace(text.find("weft = \"weft.csv\"\n"), 18, "");
  const InputError e = load_error(text);
  EXPECT_EQ(e.where().key, "fabric.weft");
  EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos);
}

TEST(LoadScene, BodyNeedsItsUnits) {
  const InputError e = load_error(std::string(kMinimal) + "[[body]]\nmesh = \"m.stl\"\nunits = \"furlong\"\n");
  EXPECT_EQ(e.where().key, "body.0.units");
  EXPECT_EQ(e.where().line, 12);
}

TEST(LoadScene, InitialShapeNeedsItsParameters) {
  const InputError e = load_error(std::string(kMinimal) + "[initial]\nshape = \"wrap\"\nradius_m = 0.2\n");
  EXPECT_EQ(e.where().key, "initial.axis_m");
}

// A seamless tube: its circumference, length and [round, along] divisions; the warp round it
// by default; it starts as a tube round the body, and nothing else starts as one.
const char* kTube =
    "[fabric]\n"                          // line 1
    "shape = \"tube\"\n"                  // line 2
    "circumference_m = 0.3\n"             // line 3
    "length_m = 0.1\n"                    // line 4
    "divisions = [30, 10]\n"              // line 5
    "warp = \"warp.csv\"\n"               // line 6
    "weft = \"weft.csv\"\n"               // line 7
    "[initial]\n"                         // line 8
    "axis_m = [0, 0]\n"                   // line 9
    "radius_m = 0.06\n"                   // line 10
    "[solver]\n"                          // line 11
    "name = \"newton\"\n"                 // line 12
    "tolerance_N = 1e-3\n";               // line 13

Scene load_text(const std::string& text) {
  test::TempDir dir;
  return load_scene(dir.write("scene.toml", text));
}

TEST(LoadScene, ReadsATube) {
  const Scene round = load_text(kTube);
  EXPECT_EQ(round.fabric.tube, FabricSpec::Tube::warp_round);
  EXPECT_EQ(round.fabric.width_m, 0.3);
  EXPECT_EQ(round.fabric.height_m, 0.1);
  EXPECT_EQ(round.fabric.divisions_warp, 30);
  EXPECT_EQ(round.fabric.divisions_weft, 10);
  EXPECT_EQ(round.initial.kind, InitialShape::Kind::tube);
}

TEST(LoadScene, ATubeWithItsWarpAlongItTurnsItsRectangle) {
  std::string text = kTube;
  text.replace(text.find("length_m"), 0, "warp_runs = \"along\"\n");
  const Scene along = load_text(text);
  EXPECT_EQ(along.fabric.tube, FabricSpec::Tube::warp_along);
  EXPECT_EQ(along.fabric.width_m, 0.1);
  EXPECT_EQ(along.fabric.height_m, 0.3);
  EXPECT_EQ(along.fabric.divisions_warp, 10);
  EXPECT_EQ(along.fabric.divisions_weft, 30);
}

TEST(LoadScene, BadTubesNameTheirKey) {
  const auto error_with = [](const std::string& from, const std::string& to) {
    std::string text = kTube;
    text.replace(text.find(from), from.size(), to);
    return load_error(text);
  };
  EXPECT_EQ(error_with("divisions = [30, 10]", "divisions = [2, 10]").where().key, "fabric.divisions");
  EXPECT_EQ(error_with("length_m = 0.1", "length_m = -0.1").where().key, "fabric.length_m");
  EXPECT_EQ(error_with("length_m = 0.1", "length_m = 0.1\nwarp_runs = \"sideways\"").where().key, "fabric.warp_runs");
  EXPECT_EQ(error_with("length_m = 0.1", "length_m = 0.1\nsize_m = [0.1, 0.1]").where().key, "fabric.size_m");
  EXPECT_EQ(error_with("radius_m = 0.06", "shape = \"flat\"").where().key, "initial.shape");
  EXPECT_EQ(error_with("radius_m = 0.06", "").where().key, "initial.radius_m");
  EXPECT_EQ(error_with("radius_m = 0.06", "radius_m = -0.06").where().key, "initial.radius_m");
  const InputError not_a_tube = load_error(std::string(kMinimal) + "[initial]\nshape = \"tube\"\nradius_m = 0.1\n");
  EXPECT_EQ(not_a_tube.where().key, "initial.shape");
  EXPECT_NE(std::string(not_a_tube.what()).find("tube fabric"), std::string::npos) << not_a_tube.what();
}

TEST(LoadScene, SelfContactHasAThicknessAndOnlyNewton) {
  std::string newton = kMinimal;
  newton.replace(newton.find("[solver]\n"), 9, "[solver]\nname = \"newton\"\n");
  const Scene scene = load_text(newton + "[self_contact]\n");
  EXPECT_TRUE(scene.self_contact.on);
  EXPECT_EQ(scene.self_contact.thickness_m, 0.5e-3);
  EXPECT_EQ(load_text(newton + "[self_contact]\nthickness_m = 1e-3\n").self_contact.thickness_m, 1e-3);
  EXPECT_EQ(load_error(newton + "[self_contact]\nthickness_m = -1e-3\n").where().key, "self_contact.thickness_m");
  EXPECT_EQ(load_error(newton + "[self_contact]\nthickness_m = 0.5\n").where().key, "self_contact.thickness_m");
  const InputError relax = load_error(std::string(kMinimal) + "[self_contact]\n");
  EXPECT_EQ(relax.where().key, "solver.name");
  EXPECT_NE(std::string(relax.what()).find("self-contact"), std::string::npos) << relax.what();
}

TEST(LoadScene, AFoldLiesInsideTheRectangle) {
  const Scene scene = load_text(std::string(kMinimal) + "[initial]\nshape = \"fold\"\nfold_at_m = 0.05\nheight_m = 0.002\n");
  EXPECT_EQ(scene.initial.kind, InitialShape::Kind::fold);
  EXPECT_EQ(scene.initial.fold_at_m, 0.05);
  EXPECT_EQ(load_error(std::string(kMinimal) + "[initial]\nshape = \"fold\"\nfold_at_m = 0.1\nheight_m = 0.002\n")
                .where().key, "initial.fold_at_m");
  EXPECT_EQ(load_error(std::string(kMinimal) + "[initial]\nshape = \"fold\"\nfold_at_m = 0.05\n").where().key,
            "initial.height_m");
}

TEST(LoadScene, ATubeIsNewtonsAlone) {
  std::string text = kTube;
  text.replace(text.find("newton"), 6, "dynamic");
  const InputError e = load_error(text);
  EXPECT_EQ(e.where().key, "solver.name");
  EXPECT_NE(std::string(e.what()).find("tube"), std::string::npos) << e.what();
}

// Without solver.continuation_levels, fabform halves the grid while both divisions stay even
// and the coarsest keeps 50 divisions, where the scene can be continued (newton, no travel);
// the scene's own key, 0 included, is kept.
TEST(LoadScene, ContinuationIsChosenFromTheFabricsSizeUnlessGiven) {
  const auto levels_for = [](const std::string& divisions, const std::string& solver) {
    std::string text = kMinimal;
    text.replace(text.find("divisions = [4, 8]"), 18, "divisions = " + divisions);
    text.replace(text.find("[solver]\n"), 9, "[solver]\n" + solver);
    return load_text(text).solver;
  };
  EXPECT_EQ(levels_for("[400, 400]", "name = \"newton\"\n").continuation_levels, 3);  // 200, 100, 50
  EXPECT_TRUE(levels_for("[400, 400]", "name = \"newton\"\n").continuation_chosen);
  EXPECT_EQ(levels_for("[200, 100]", "name = \"newton\"\n").continuation_levels, 1);  // 100 x 50
  EXPECT_EQ(levels_for("[1000, 1000]", "name = \"newton\"\n").continuation_levels, 3);  // 125 does not halve
  EXPECT_EQ(levels_for("[99, 400]", "name = \"newton\"\n").continuation_levels, 0);
  EXPECT_EQ(levels_for("[40, 40]", "name = \"newton\"\n").continuation_levels, 0);
  EXPECT_EQ(levels_for("[400, 400]", "").continuation_levels, 0);  // relax
  const SolverSpec given = levels_for("[400, 400]", "name = \"newton\"\ncontinuation_levels = 0\n");
  EXPECT_EQ(given.continuation_levels, 0);
  EXPECT_FALSE(given.continuation_chosen);
}

TEST(LoadScene, OverridesReplaceValuesByDottedKey) {
  test::TempDir dir;
  const std::string path = dir.write("scene.toml", kMinimal);
  const Scene scene = load_scene(path, {{"solver.tolerance_N", "2.5e-4"},
                                        {"fabric.divisions", "[10, 20]"},
                                        {"constraint.0.axes", "xy"},
                                        {"fabric.warp", "other.csv"}});
  EXPECT_EQ(scene.solver.relax.tolerance_N, 2.5e-4);
  EXPECT_EQ(scene.fabric.divisions_warp, 10);
  EXPECT_EQ(scene.constraints[0].axes, kLockX | kLockY);
  EXPECT_EQ(scene.warp_path, dir.path("other.csv"));
}

TEST(LoadScene, BadOverrideIsBlamedOnTheCommandLine) {
  const InputError e = load_error(kMinimal, {{"solver.tolerance_N", "fast"}});
  EXPECT_EQ(e.where().file, "command line --set");
  EXPECT_EQ(e.where().key, "solver.tolerance_N");
  const InputError unknown = load_error(kMinimal, {{"solver.speed", "3"}});
  EXPECT_EQ(unknown.where().key, "solver.speed");
  const InputError index = load_error(kMinimal, {{"constraint.5.axes", "x"}});
  EXPECT_EQ(index.where().key, "constraint.5.axes");
  for (const char* key : {"", ".", "solver."})  // a study's keys come without parse_override's check
    EXPECT_EQ(load_error(kMinimal, {{key, "3"}}).where().file, "command line --set") << "'" << key << "'";
}

TEST(ParseOverride, SplitsAtTheFirstEquals) {
  const SceneOverride o = parse_override("fabric.warp=a=b.csv");
  EXPECT_EQ(o.key, "fabric.warp");
  EXPECT_EQ(o.value, "a=b.csv");
  EXPECT_THROW(parse_override("fabric.warp"), InputError);
  EXPECT_THROW(parse_override("=3"), InputError);
}

}  // namespace
}  // namespace fabform::scene_toml_test
