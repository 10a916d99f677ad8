// study.json: what `--resume` reads back; a study with specimens keeps them, and a record whose
// specimens do not group its cases is refused naming the file.
#include "fabform/study/study_record.hpp"

#include <gtest/gtest.h>

#include "fabform/study/study_cases.hpp"
#include "support/temp_dir.hpp"

namespace fabform::study_record_test {
namespace {

StudySpec two_cases_of_two_specimens() {
  StudySpec spec;
  spec.name = "s";
  spec.scene = "/nowhere/scene.toml";
  spec.varied = {"solver.name"};
  spec.figures = {"residual_N"};
  spec.cases = {{{{"solver.name", "'newton'", "newton", {}}}}, {{{"solver.name", "'relax'", "relax", {}}}}};
  spec.specimens = 2;
  spec.cases = specimen_cases(spec.cases, 2, {});
  spec.varied.push_back(kSpecimenSeedKey);
  return spec;
}

TEST(StudyRecord, SpecimensRoundTrip) {
  test::TempDir dir;
  write_study_record(dir.root().string(), two_cases_of_two_specimens());
  const StudySpec back = read_study_record(dir.root().string());
  EXPECT_EQ(back.specimens, 2);
  ASSERT_EQ(back.cases.size(), 4u);
  EXPECT_EQ(back.cases[3].values[1].toml, "2");
  EXPECT_EQ(back.specimens_where.file, study_record_path(dir.root().string()));
}

TEST(StudyRecord, SpecimensThatDoNotGroupTheCasesAreRefused) {
  test::TempDir dir;
  StudySpec spec = two_cases_of_two_specimens();
  spec.specimens = 3;
  write_study_record(dir.root().string(), spec);
  try {
    read_study_record(dir.root().string());
    ADD_FAILURE() << "a record of 4 cases in specimens of 3 was read";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, study_record_path(dir.root().string()));
    EXPECT_NE(error.message().find("do not group"), std::string::npos) << error.what();
  }
}

// Each run of specimens counts its seeds 1 … N: a record with a seed out of place is refused.
TEST(StudyRecord, SpecimenSeedsOutOfPlaceAreRefused) {
  test::TempDir dir;
  StudySpec spec = two_cases_of_two_specimens();
  spec.cases[2].values.back().toml = "3";
  write_study_record(dir.root().string(), spec);
  try {
    read_study_record(dir.root().string());
    ADD_FAILURE() << "a record whose third case has seed 3 was read";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, study_record_path(dir.root().string()));
    EXPECT_NE(error.message().find("case 2 should be specimen 1"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace fabform::study_record_test
