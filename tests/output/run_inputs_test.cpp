// What a run was made from, as result.json records it and a resume reads it back.
#include <gtest/gtest.h>

#include <string>

#include "fabform/error.hpp"
#include "fabform/io/sha256.hpp"
#include "fabform/output/run_inputs.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "support/cli.hpp"
#include "support/temp_dir.hpp"

namespace fabform::run_inputs_test {
namespace {

class RunInputsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("warp.csv", "strain,tension_N_per_m\n0,0\n1,500\n");
    dir.write("weft.csv", "strain,tension_N_per_m\n0,0\n1,300\n");
    dir.write("block.obj", "v 0 0 -1\nv 1 0 -1\nv 0 1 -1\nf 1 2 3\n");
    dir.write("scene.toml",
              "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [2, 2]\nwarp = \"warp.csv\"\nweft = \"weft.csv\"\n"
              "[[body]]\nname = \"block\"\nmesh = \"block.obj\"\nunits = \"m\"\n");
  }
  RunInputs describe() const {
    const std::vector<SceneOverride> overrides = {{"solver.name", "newton"}};
    return describe_inputs(load_scene(dir.path("scene.toml"), overrides), overrides);
  }
  test::TempDir dir;
};

TEST_F(RunInputsTest, EveryFileReadIsHashed) {
  const RunInputs inputs = describe();
  EXPECT_EQ(inputs.scene_file, dir.path("scene.toml"));
  ASSERT_EQ(inputs.files.size(), 4u);
  EXPECT_EQ(inputs.files[0].role, "scene");
  EXPECT_EQ(inputs.files[1].role, "warp");
  EXPECT_EQ(inputs.files[2].role, "weft");
  EXPECT_EQ(inputs.files[3].role, "body block");
  EXPECT_EQ(inputs.files[1].sha256, sha256_of_file(dir.path("warp.csv")));
  EXPECT_EQ(input_change(inputs, describe()), "");
}

TEST_F(RunInputsTest, AChangedFileIsNamed) {
  const RunInputs before = describe();
  dir.write("weft.csv", "strain,tension_N_per_m\n0,0\n1,301\n");
  const std::string change = input_change(before, describe());
  EXPECT_NE(change.find("weft"), std::string::npos) << change;
  EXPECT_NE(change.find("has changed"), std::string::npos) << change;
}

// A shear table is read as well: it is hashed, and a change to it is named.
TEST_F(RunInputsTest, TheShearTableIsHashed) {
  dir.write("shear.csv", "strain,tension_N_per_m\n0,0\n1,50\n");
  dir.write("scene.toml", test::slurp(dir.path("scene.toml")) + "[shear]\nmaterial = \"shear.csv\"\n");
  const RunInputs before = describe();
  ASSERT_EQ(before.files.size(), 5u);
  EXPECT_EQ(before.files[3].role, "shear");
  dir.write("shear.csv", "strain,tension_N_per_m\n0,0\n1,51\n");
  EXPECT_NE(input_change(before, describe()).find("shear"), std::string::npos);
}

// A shear rigidity G is a number of the scene, no file: nothing more is hashed (a run with one
// failed with "cannot be read" when its empty table path was hashed).
TEST_F(RunInputsTest, AShearRigidityReadsNoFile) {
  dir.write("scene.toml", test::slurp(dir.path("scene.toml")) + "[shear]\nrigidity_N_m = 41.0\n");
  const RunInputs inputs = describe();
  ASSERT_EQ(inputs.files.size(), 4u);
  for (const auto& file : inputs.files) EXPECT_NE(file.role, "shear");
}

TEST_F(RunInputsTest, ReadBackFromResultJson) {
  dir.write("result.json",
            "{\"scene_file\": \"/s/scene.toml\", \"overrides\": [{\"key\": \"solver.C\", \"value\": \"3\"}],"
            " \"inputs\": [{\"role\": \"scene\", \"path\": \"/s/scene.toml\", \"sha256\": \"ab\"}]}");
  const RunInputs inputs = read_run_inputs(dir.path("result.json"));
  EXPECT_EQ(inputs.scene_file, "/s/scene.toml");
  ASSERT_EQ(inputs.overrides.size(), 1u);
  EXPECT_EQ(inputs.overrides[0].key, "solver.C");
  EXPECT_EQ(inputs.overrides[0].value, "3");
  ASSERT_EQ(inputs.files.size(), 1u);
  EXPECT_EQ(inputs.files[0].sha256, "ab");
}

TEST_F(RunInputsTest, ResultJsonWithoutInputsIsRefusedNamingIt) {
  for (const char* text : {"", "{}", "{\"scene_file\": 3}", "[1, 2]", "{\"scene_file\": \"a\", \"overrides\": []}"}) {
    dir.write("result.json", text);
    try {
      read_run_inputs(dir.path("result.json"));
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("result.json"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace fabform::run_inputs_test
