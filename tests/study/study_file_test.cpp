// Study files: the shipped studies read and check against their scenes; every bad input of the
// issue is one error naming the study file, the line and the key, found before any case runs.
#include "fabform/study/study_file.hpp"

#include <gtest/gtest.h>

#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform {
namespace {

std::string study_text(const std::string& body, const std::string& figures = "[\"residual_N\"]") {
  return "[study]\nscene = \"" + test::source_path("scenes/dome.toml") + "\"\nfigures = " + figures +
         "\n\n[study.set]\n\"fabric.divisions\" = [10, 10]\n\n" + body;
}

InputError error_of(const std::string& text) {
  test::TempDir dir;
  const std::string path = dir.write("s.toml", text);
  try {
    load_study(path);
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, path);
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    return error;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError({}, "");
}

TEST(StudyFile, ShippedStudiesReadAndFitTheirScenes) {
  for (const char* name : {"dome_tolerance_solver", "cup_friction_depth", "cusick_fabrics"}) {
    const StudySpec spec = load_study(test::source_path(std::string("studies/") + name + ".toml"));
    EXPECT_EQ(spec.name, name);
    EXPECT_FALSE(spec.cases.empty());
    EXPECT_FALSE(spec.figures.empty());
  }
  EXPECT_EQ(load_study(test::source_path("studies/dome_tolerance_solver.toml")).cases.size(), 12u);
}

TEST(StudyFile, GridValuesAreShownAsWrittenAndPassedAsToml) {
  test::TempDir dir;
  const StudySpec spec = load_study(dir.write("s.toml", study_text(
      "[grid]\n\"solver.tolerance_N\" = [1e-5, 2.0]\nsolver.name = [\"newton\"]\n")));
  ASSERT_EQ(spec.varied, (std::vector<std::string>{"solver.tolerance_N", "solver.name"}));
  EXPECT_EQ(spec.cases[0].values[0].text, "1e-05");
  EXPECT_EQ(spec.cases[1].values[0].toml, "2.0");
  EXPECT_EQ(spec.cases[0].values[1].toml, "'newton'");
  EXPECT_EQ(spec.cases[0].values[1].text, "newton");
}

TEST(StudyFile, KeysKeepTheFilesOrderAndArraysTheirShortestNumbers) {
  test::TempDir dir;
  const StudySpec spec = load_study(dir.write("s.toml", study_text(
      "[grid]\n\"solver.tolerance_N\" = [1e-5]\n\"initial.height_m\" = [0.04]\n\"fabric.origin_m\" = [[0.0, 0.1, 0.036]]\n")));
  EXPECT_EQ(spec.varied, (std::vector<std::string>{"solver.tolerance_N", "initial.height_m", "fabric.origin_m"}));
  EXPECT_EQ(spec.cases[0].values[2].toml, "[0.0, 0.1, 0.036]");
}

TEST(StudyFile, AKeyTheSceneLacksNamesTheStudyLineAndKey) {
  const InputError e = error_of(study_text("[grid]\n\"solver.tolerence_N\" = [1e-5]\n"));
  EXPECT_EQ(e.where().line, 9);
  EXPECT_EQ(e.where().key, "solver.tolerence_N");
  EXPECT_NE(e.message().find("unknown key"), std::string::npos) << e.what();
}

TEST(StudyFile, AValueTheSceneRefusesNamesTheStudyLine) {
  const InputError e = error_of(study_text("[[case]]\n\"body.0.friction\" = 0.2\n\n[[case]]\n\"body.0.friction\" = -1.0\n"));
  EXPECT_EQ(e.where().line, 12);
  EXPECT_EQ(e.where().key, "body.0.friction");
}

TEST(StudyFile, AnEmptyListOfValues) {
  const InputError e = error_of(study_text("[grid]\n\"solver.tolerance_N\" = []\n"));
  EXPECT_EQ(e.where().line, 9);
  EXPECT_NE(e.message().find("empty list"), std::string::npos);
}

TEST(StudyFile, ASampleWithoutASeed) {
  const InputError e = error_of(study_text("[sample]\ncount = 4\n\n[sample.ranges]\n\"solver.tolerance_N\" = [1e-6, 1e-3]\n"));
  EXPECT_EQ(e.where().key, "sample.seed");
  EXPECT_EQ(e.where().line, 8);
  EXPECT_NE(e.message().find("seed"), std::string::npos);
}

TEST(StudyFile, AFigureNoResultHas) {
  const InputError e = error_of(study_text("[grid]\n\"solver.tolerance_N\" = [1e-5]\n", "[\"residual_N\",\n  \"drape_coefficient\"]"));
  EXPECT_EQ(e.where().line, 4);
  EXPECT_EQ(e.where().key, "study.figures");
  EXPECT_NE(e.message().find("'drape_coefficient'"), std::string::npos);
}

TEST(StudyFile, CasesMustSetTheSameKeysAndOneKindOfCases) {
  EXPECT_EQ(error_of(study_text("[[case]]\n\"solver.name\" = \"newton\"\n\n[[case]]\n\"solver.tolerance_N\" = 1e-5\n")).where().line, 11);
  EXPECT_NE(error_of(study_text("[grid]\n\"solver.name\" = [\"newton\"]\n\n[[case]]\n\"solver.name\" = \"newton\"\n"))
                .message().find("one way"), std::string::npos);
  EXPECT_NE(error_of(study_text("")).message().find("one way"), std::string::npos);
}

}  // namespace
}  // namespace fabform
