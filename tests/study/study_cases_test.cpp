// A study's cases: a grid is every combination in nested-loop order; a Latin hypercube uses every
// stratum of every range once, stays within its ranges and is the same for the same seed.
#include "fabform/study/study_cases.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace fabform::study_cases_test {
namespace {

StudyValue value(const std::string& key, const std::string& text) { return {key, text, text, {}}; }

TEST(StudyCases, GridIsEveryCombinationTheLastKeyFastest) {
  const std::vector<StudyCase> cases = grid_cases({{"a", {value("a", "1"), value("a", "2")}},
                                                   {"b", {value("b", "x"), value("b", "y"), value("b", "z")}}});
  ASSERT_EQ(cases.size(), 6u);
  EXPECT_EQ(cases[0].values[0].text + cases[0].values[1].text, "1x");
  EXPECT_EQ(cases[2].values[0].text + cases[2].values[1].text, "1z");
  EXPECT_EQ(cases[5].values[0].text + cases[5].values[1].text, "2z");
}

TEST(StudyCases, LatinHypercubeUsesEveryStratumOnceAndRepeatsForItsSeed) {
  const int count = 10;
  const std::vector<SampleRange> ranges = {{"mu", 0.1, 0.6, false, {}}, {"steps", 1, 10, true, {}}};
  const std::vector<StudyCase> cases = latin_hypercube(ranges, count, 42);
  ASSERT_EQ(cases.size(), static_cast<std::size_t>(count));
  std::set<int> strata_mu, steps;
  for (const StudyCase& c : cases) {
    const double mu = std::stod(c.values[0].text);
    EXPECT_GE(mu, 0.1);
    EXPECT_LE(mu, 0.6);
    strata_mu.insert(static_cast<int>((mu - 0.1) / 0.05));
    steps.insert(std::stoi(c.values[1].toml));
  }
  EXPECT_EQ(strata_mu.size(), static_cast<std::size_t>(count));
  EXPECT_EQ(steps.size(), 10u) << "ten whole numbers in [1, 10], one per stratum";
  const std::vector<StudyCase> again = latin_hypercube(ranges, count, 42);
  const std::vector<StudyCase> other = latin_hypercube(ranges, count, 43);
  bool same = true, differs = false;
  for (int i = 0; i < count; ++i) {
    same = same && again[static_cast<std::size_t>(i)].values[0].text == cases[static_cast<std::size_t>(i)].values[0].text;
    differs = differs || other[static_cast<std::size_t>(i)].values[0].text != cases[static_cast<std::size_t>(i)].values[0].text;
  }
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
}

TEST(StudyCases, SpecimensRepeatEveryCaseWithSeedsOneToN) {
  const std::vector<StudyCase> cases = {{{{"solver.name", "'newton'", "newton", {}}}}, {{{"solver.name", "'relax'", "relax", {}}}}};
  const std::vector<StudyCase> specimens = specimen_cases(cases, 2, {"s.toml", 3, "study.specimens"});
  ASSERT_EQ(specimens.size(), 4u);
  const char* names[] = {"newton", "newton", "relax", "relax"};
  for (std::size_t i = 0; i < 4; ++i) {
    ASSERT_EQ(specimens[i].values.size(), 2u);
    EXPECT_EQ(specimens[i].values[0].text, names[i]);
    EXPECT_EQ(specimens[i].values[1].key, kSpecimenSeedKey);
    EXPECT_EQ(specimens[i].values[1].toml, std::to_string(1 + i % 2));
    EXPECT_EQ(specimens[i].values[1].where.line, 3);
  }
}

}  // namespace
}  // namespace fabform::study_cases_test
