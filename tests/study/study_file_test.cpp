// Study files: the shipped studies read and check against their scenes; every bad input of the
// issue is one error naming the study file, the line and the key, found before any case runs.
#include "fabform/study/study_file.hpp"

#include <gtest/gtest.h>

#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::study_file_test {
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
  for (const char* name : {"dome_tolerance_solver", "cup_friction_depth", "cusick_fabrics", "cusick_measured",
                           "cusick_bending_friction", "cusick_shear_friction"}) {
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

// [study] specimens = N: each case N times, initial.seed 1 … N its last column (the dome with a
// start imperfection, so that the seeds differ).
std::string specimens_text(const std::string& specimens, const std::string& set, const std::string& body) {
  return "[study]\nscene = \"" + test::source_path("scenes/dome.toml") + "\"\nfigures = [\"residual_N\"]\nspecimens = " +
         specimens + "\n\n[study.set]\n\"fabric.divisions\" = [10, 10]\n" + set + "\n" + body;
}

TEST(StudyFile, SpecimensRunEveryCaseWithSeedsOneToN) {
  test::TempDir dir;
  const StudySpec spec = load_study(dir.write("s.toml", specimens_text(
      "3", "\"initial.perturbation_m\" = 1e-4\n", "[grid]\n\"solver.tolerance_N\" = [1e-5, 1e-6]\n")));
  EXPECT_EQ(spec.specimens, 3);
  ASSERT_EQ(spec.varied, (std::vector<std::string>{"solver.tolerance_N", "initial.seed"}));
  ASSERT_EQ(spec.cases.size(), 6u);
  const char* tolerance[] = {"1e-05", "1e-05", "1e-05", "1e-06", "1e-06", "1e-06"};
  const char* seed[] = {"1", "2", "3", "1", "2", "3"};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(spec.cases[i].values[0].text, tolerance[i]);
    EXPECT_EQ(spec.cases[i].values[1].toml, seed[i]);
  }
}

TEST(StudyFile, SpecimensAloneAreTheBaseScenesOwn) {
  test::TempDir dir;
  const StudySpec spec = load_study(dir.write("s.toml", specimens_text("2", "\"initial.perturbation_m\" = 1e-4\n", "")));
  ASSERT_EQ(spec.varied, std::vector<std::string>{"initial.seed"});
  ASSERT_EQ(spec.cases.size(), 2u);
  EXPECT_EQ(spec.cases[1].values.size(), 1u);
  EXPECT_EQ(spec.cases[1].values[0].toml, "2");
}

TEST(StudyFile, SpecimensThatCouldNotDifferOrWhoseSeedIsSetAreRefused) {
  const InputError same = error_of(specimens_text("4", "", "[grid]\n\"solver.tolerance_N\" = [1e-5]\n"));
  EXPECT_EQ(same.where().line, 4);
  EXPECT_EQ(same.where().key, "study.specimens");
  EXPECT_NE(same.message().find("every specimen would be the same run"), std::string::npos) << same.what();
  const InputError seeded = error_of(specimens_text(
      "4", "\"initial.perturbation_m\" = 1e-4\n", "[grid]\n\"initial.seed\" = [1, 2]\n"));
  EXPECT_EQ(seeded.where().line, 11);
  EXPECT_EQ(seeded.where().key, "initial.seed");
  const InputError none = error_of(specimens_text("0", "", "[grid]\n\"solver.tolerance_N\" = [1e-5]\n"));
  EXPECT_EQ(none.where().line, 4);
  EXPECT_NE(none.message().find("between 1 and 1000"), std::string::npos) << none.what();
  // Specimens alone are the base scene's; one specimen is an ordinary study, which needs cases.
  EXPECT_NE(error_of(specimens_text("1", "", "")).message().find("one way"), std::string::npos);
  test::TempDir dir;
  const StudySpec one = load_study(dir.write("s.toml", specimens_text("1", "", "[grid]\n\"solver.tolerance_N\" = [1e-5]\n")));
  EXPECT_EQ(one.varied, std::vector<std::string>{"solver.tolerance_N"});
}

}  // namespace
}  // namespace fabform::study_file_test
