// study_specimens.csv: each case's specimens reduced to what a drape tester reports, the mean
// and scatter over the specimens that converged; one that stopped short, was cancelled or left
// no result is counted but gives no reading.
#include "fabform/study/specimen_summary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "fabform/study/study_case.hpp"
#include "support/temp_dir.hpp"

namespace fabform::specimen_summary_test {
namespace {

void write_result(test::TempDir& dir, int index, bool converged, int folds, double coefficient) {
  std::filesystem::create_directories(case_folder(dir.root().string(), index));
  std::ostringstream json;
  json << R"({"converged": )" << (converged ? "true" : "false") << R"(, "termination": ")"
       << (converged ? "converged" : "not converged") << R"(", "iterations": 5, "wall_seconds": 1.0,
            "drape_coefficient": )" << coefficient << R"(, "drape": {"folds": )" << folds << "}}";
  char name[32];
  std::snprintf(name, sizeof name, "cases/%04d/result.json", index);
  dir.write(name, json.str());
}

StudySpec two_cases_of_three_specimens() {
  StudySpec spec;
  spec.varied = {"fabric.mesh", "initial.seed"};
  spec.figures = {"drape.folds", "drape_coefficient"};
  spec.specimens = 3;
  for (const char* mesh : {"arc", "jittered"})
    for (const char* seed : {"1", "2", "3"}) spec.cases.push_back({{{"fabric.mesh", "", mesh, {}}, {"initial.seed", seed, seed, {}}}});
  return spec;
}

TEST(SpecimenSummary, MeanAndScatterOverTheSpecimensThatConverged) {
  test::TempDir dir;
  write_result(dir, 0, true, 9, 0.25);
  write_result(dir, 1, true, 10, 0.75);
  write_result(dir, 2, false, 4, 0.9);  // stopped short: counted, no reading
  write_result(dir, 3, true, 8, 0.5);
  write_result(dir, 4, true, 12, 0.1);  // its run was cancelled after all: the ending wins
  EXPECT_EQ(specimen_summary(two_cases_of_three_specimens(), dir.root().string(), {{4, "cancelled"}}),
            "cases,fabric.mesh,specimens,finished,converged,drape.folds mean,drape.folds sd,drape.folds min,"
            "drape.folds max,drape_coefficient mean,drape_coefficient sd,drape_coefficient min,drape_coefficient max\n"
            "0-2,arc,3,3,2,9.5,0.70710678118654757,9,10,0.5,0.35355339059327379,0.25,0.75\n"
            "3-5,jittered,3,1,1,8,,8,8,0.5,,0.5,0.5\n");
}

TEST(SpecimenSummary, TheDeviationIsTheSampleOneOfManyReadings) {
  test::TempDir dir;
  StudySpec spec = two_cases_of_three_specimens();
  const double coefficients[] = {0.3612, 0.3701, 0.3555, 0.41, 0.39, 0.2};
  for (int i = 0; i < 6; ++i) write_result(dir, i, true, 9 + i % 2, coefficients[i]);
  std::istringstream table(specimen_summary(spec, dir.root().string(), {}));
  std::string line;
  std::getline(table, line);
  for (int row = 0; row < 2; ++row) {
    std::getline(table, line);
    std::vector<double> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell == "arc" || cell == "jittered" || cell.find('-') != std::string::npos ? 0.0 : std::stod(cell));
    double mean = 0.0, squares = 0.0;
    for (int k = 0; k < 3; ++k) mean += coefficients[3 * row + k] / 3.0;
    for (int k = 0; k < 3; ++k) squares += std::pow(coefficients[3 * row + k] - mean, 2);
    // Two ways of summing 3 numbers of order 0.4 agree to a few ulps of the sum.
    EXPECT_NEAR(cells[9], mean, 4e-16);
    EXPECT_NEAR(cells[10], std::sqrt(squares / 2.0), 1e-15);
  }
}

}  // namespace
}  // namespace fabform::specimen_summary_test
