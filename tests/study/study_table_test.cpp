// study.csv: a row per case in order, values as written, figures at full precision from each
// case's result.json, a strain peak as its strain; a case without a finished result is a row
// marked with how it ended.
#include "fabform/study/study_table.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "fabform/study/study_case.hpp"
#include "support/cli.hpp"
#include "support/temp_dir.hpp"

namespace fabform::study_table_test {
namespace {

TEST(StudyTable, RowsComeFromResultsAndEndings) {
  test::TempDir dir;
  StudySpec spec;
  spec.varied = {"fabric.divisions", "solver.name"};
  spec.figures = {"residual_N", "figures.max_warp_strain"};
  for (const char* solver : {"newton", "relax", "dynamic"})
    spec.cases.push_back({{{"fabric.divisions", "[ 1, 2 ]", "[ 1, 2 ]", {}}, {"solver.name", "", solver, {}}}});
  std::filesystem::create_directories(case_folder(dir.root().string(), 0));
  dir.write("cases/0000/result.json",
            R"({"converged": true, "termination": "converged", "iterations": 7, "wall_seconds": 0.25,
                "residual_N": 1.2345678901234566e-07, "figures": {"max_warp_strain": {"strain": 0.1, "at_m": [0, 0, 0]}}})");
  const std::string table = study_table(spec, dir.root().string(), {{1, "cancelled"}});
  EXPECT_EQ(table,
            "case,fabric.divisions,solver.name,residual_N,figures.max_warp_strain,converged,termination,iterations,wall_seconds\n"
            "0,\"[ 1, 2 ]\",newton,1.2345678901234566e-07,0.10000000000000001,true,converged,7,0.25\n"
            "1,\"[ 1, 2 ]\",relax,,,false,cancelled,,\n"
            "2,\"[ 1, 2 ]\",dynamic,,,false,missing,,\n");
}

}  // namespace
}  // namespace fabform::study_table_test
