// `fabform study` on the real binary: a small dome study in the local pool writes a run folder
// per case, study.json, study.csv and study.html; --resume redoes only a case whose result is
// gone; every figure result_figures.hpp names for a scene is in its real results (a drape test
// and a run in load steps); bad input is one line, exit status 2, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fabform/scene/scene_toml.hpp"
#include "fabform/study/result_figures.hpp"
#include "support/cli.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::study_command_test {
namespace {

namespace fs = std::filesystem;
using test::slurp;

std::string dome_study(const std::string& grid, const std::string& figure = "figures.max_warp_strain") {
  return "[study]\nname = \"small\"\nscene = \"" + test::source_path("scenes/dome.toml") +
         "\"\nfigures = [\"residual_recomputed_N\", \"" + figure + "\"]\n\n[study.set]\n"
         "\"fabric.divisions\" = [12, 12]\n\n" + (grid.empty() ? "" : "[grid]\n" + grid);
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The table without its wall seconds, which differ from run to run.
std::string without_wall_seconds(const std::string& table) {
  std::string out;
  for (const std::string& line : lines(table)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

// The dotted paths of the numbers in a JSON object, through objects only (not into arrays).
std::vector<std::string> numbers_in(const nlohmann::json& object, const std::string& prefix = "") {
  std::vector<std::string> paths;
  for (const auto& [key, value] : object.items()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object()) {
      for (std::string& inner : numbers_in(value, path)) paths.push_back(std::move(inner));
    } else if (value.is_number()) {
      paths.push_back(path);
    }
  }
  return paths;
}

TEST(StudyCommand, LocalPoolWritesEveryCaseTheTableAndTheReport) {
  test::TempDir dir;
  dir.write("s.toml", dome_study("\"solver.name\" = [\"newton\", \"relax\"]\n\"solver.tolerance_N\" = [1e-4, 1e-6]\n"));
  const test::Outcome done = test::run_fabform(dir, "study s.toml --out out --jobs 2");
  ASSERT_EQ(done.status, 0) << done.err;
  const std::vector<std::string> table = lines(slurp(dir.path("out/study.csv")));
  ASSERT_EQ(table.size(), 5u);
  EXPECT_EQ(table[0], "case,solver.name,solver.tolerance_N,residual_recomputed_N,figures.max_warp_strain,"
                      "converged,termination,iterations,wall_seconds");
  EXPECT_EQ(table[4].rfind("3,relax,1e-06,", 0), 0u) << table[4];
  EXPECT_NE(table[4].find(",true,converged,"), std::string::npos);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(fs::exists(dir.path("out/cases/000" + std::to_string(i) + "/result.json")));
  EXPECT_TRUE(fs::exists(dir.path("out/study.json")));
  EXPECT_TRUE(fs::exists(dir.path("out/study.html"))) << done.err;
  EXPECT_NE(done.err.find("4/4 cases done"), std::string::npos) << done.err;

  // A case's result lost: --resume runs it alone, and the table is what it was.
  const std::string before = slurp(dir.path("out/study.csv"));
  const std::string untouched = slurp(dir.path("out/cases/0000/result.json"));
  fs::remove_all(dir.path("out/cases/0002"));
  const test::Outcome resumed = test::run_fabform(dir, "study --resume out");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("4 cases (1 to run)"), std::string::npos) << resumed.err;
  EXPECT_EQ(slurp(dir.path("out/cases/0000/result.json")), untouched);
  EXPECT_EQ(without_wall_seconds(slurp(dir.path("out/study.csv"))), without_wall_seconds(before));

  // A new study is never written into a study's folder.
  const test::Outcome again = test::run_fabform(dir, "study s.toml --out out");
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("--resume"), std::string::npos);
}

TEST(StudyCommand, EveryKnownFigureIsInRealResults) {
  test::TempDir dir;
  const std::pair<const char*, std::string> studies[] = {
      {"cusick", "[grid]\n\"fabric.divisions\" = [12]\n"},
      {"cup", "[study.set]\n\"body.0.path.steps\" = 2\n[grid]\n\"fabric.divisions\" = [[10, 10]]\n"}};
  for (const auto& [scene, cases] : studies) {
    const std::string scene_file = test::source_path(std::string("scenes/") + scene + ".toml");
    std::string figures;
    for (const std::string& path : result_figure_paths(load_scene(scene_file))) figures += (figures.empty() ? "\"" : ", \"") + path + "\"";
    EXPECT_NE(figures.find(std::string(scene) == "cusick" ? "\"drape.folds\"" : "\"load_steps\""), std::string::npos);
    dir.write(std::string(scene) + ".toml", "[study]\nscene = \"" + scene_file + "\"\nfigures = [" + figures + "]\n" + cases);
    const test::Outcome done = test::run_fabform(dir, std::string("study ") + scene + ".toml --out " + scene + "_out --jobs 1");
    ASSERT_TRUE(done.status == 0 || done.status == 3) << done.err;  // converged or not, a result holds every figure
    const std::vector<std::string> table = lines(slurp(dir.path(std::string(scene) + "_out/study.csv")));
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[1].find(",,"), std::string::npos) << scene << ": a figure is missing:\n" << table[0] << "\n" << table[1];
    // And the other way: every number result.json holds outside its lists is a known figure.
    const std::vector<std::string> known = result_figure_paths(load_scene(scene_file));
    for (const std::string& path : numbers_in(nlohmann::json::parse(slurp(dir.path(std::string(scene) + "_out/cases/0000/result.json")))))
      EXPECT_NE(std::find(known.begin(), known.end(), path), known.end()) << scene << ": " << path << " is not a known figure";
  }
}

TEST(StudyCommand, BadInputIsOneLineAndWritesNothing) {
  test::TempDir dir;
  dir.write("unknown.toml", dome_study("\"body.0.frictio\" = [0.1]\n"));
  dir.write("empty.toml", dome_study("\"solver.tolerance_N\" = []\n"));
  dir.write("seedless.toml", dome_study("") + "[sample]\ncount = 3\n[sample.ranges]\n\"solver.tolerance_N\" = [1e-6, 1e-4]\n");
  dir.write("figure.toml", dome_study("\"solver.tolerance_N\" = [1e-4]\n", "figures.max_strain"));
  dir.write("good.toml", dome_study("\"solver.tolerance_N\" = [1e-4]\n"));
  const std::pair<std::string, std::string> cases[] = {
      {"study unknown.toml --out out", "unknown.toml:10: body.0.frictio: unknown key"},
      {"study empty.toml --out out", "empty.toml:10: solver.tolerance_N: empty list"},
      {"study seedless.toml --out out", "seedless.toml:9: sample.seed: missing"},
      {"study figure.toml --out out", "figure.toml:4: study.figures: 'figures.max_strain'"},
      {"study good.toml --out out --jobs 0", "--jobs"},
      {"study good.toml --out out --partition p", "--partition"},
      {"study --resume nowhere", "no study here"}};
  for (const auto& [arguments, expected] : cases) {
    const test::Outcome done = test::run_fabform(dir, arguments);
    EXPECT_EQ(done.status, 2) << arguments;
    EXPECT_EQ(test::error_line_count(done.err), 1) << done.err;
    EXPECT_NE(done.err.find(expected), std::string::npos) << arguments << ": " << done.err;
    EXPECT_FALSE(fs::exists(dir.path("out"))) << arguments;
  }
  // No sbatch on the PATH: said plainly, nothing submitted, nothing written.
  const std::string command = "cd '" + dir.root().string() + "' && PATH=/nonexistent '" + test::fabform_binary() +
                              "' study good.toml --out out --on slurm 2>err.txt";
  const int raw = std::system(command.c_str());
  EXPECT_EQ(WEXITSTATUS(raw), 2);
  const std::string err = slurp(dir.path("err.txt"));
  EXPECT_NE(err.find("sbatch is not on the PATH"), std::string::npos) << err;
  EXPECT_EQ(test::line_count(err), 1) << err;
  EXPECT_FALSE(fs::exists(dir.path("out")));
}

}  // namespace
}  // namespace fabform::study_command_test
