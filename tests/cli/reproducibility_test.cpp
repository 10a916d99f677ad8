// The same scene and version give the same bits, on one thread or two: every solver on a grid
// large enough for its loops to run in parallel (10⁴ nodes), compared file by file. Only the
// timing fields differ between runs (wall_seconds, solve_seconds, the history's seconds), and
// the thread count recorded in result.json.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "fabform/io/sha256.hpp"
#include "fabform/output/checkpoint.hpp"
#include "support/cli.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::reproducibility_test {
namespace {

using test::slurp;

// result.json without what says how long the run took or on how many threads.
nlohmann::json without_timing(const std::string& text) {
  nlohmann::json j = nlohmann::json::parse(text);
  for (const char* key : {"wall_seconds", "solve_seconds", "threads"}) j.erase(key);
  auto& overrides = j["overrides"];
  for (auto o = overrides.begin(); o != overrides.end();)
    o = (*o)["key"] == "solver.threads" ? overrides.erase(o) : o + 1;
  return j;
}

// convergence.csv without its seconds column (the third).
std::string without_seconds(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, kept;
  while (std::getline(in, line)) {
    const auto second = line.find(',', line.find(',') + 1);
    kept += line.substr(0, second) + line.substr(line.find(',', second + 1)) + '\n';
  }
  return kept;
}

struct Case {
  const char* solver;
  int iterations;
};

class Reproducible : public ::testing::TestWithParam<Case> {
 protected:
  std::string run(const std::string& out, int threads) {
    const std::string arguments = "run '" + test::source_path("scenes/dome.toml") + "' --out " + out +
                                  " --quiet --set fabric.divisions=[99,99] --solver " + GetParam().solver +
                                  " --max-iter " + std::to_string(GetParam().iterations) +
                                  " --threads " + std::to_string(threads);
    const test::Outcome o = test::run_fabform(dir, arguments);
    EXPECT_EQ(o.status, 3) << o.err;  // stopped at its cap, on purpose
    return out;
  }
  void expect_same(const std::string& a, const std::string& b) {
    for (const char* file : {"fabric.obj", "fabric.vtk"})
      EXPECT_TRUE(slurp(dir.path(a + "/" + file)) == slurp(dir.path(b + "/" + file))) << a << " " << b << " " << file;
    // checkpoint.bin holds the history's seconds too: its state is compared, bit for bit.
    const Checkpoint ca = read_checkpoint(dir.path(a + "/checkpoint.bin"), 10000, 1);
    const Checkpoint cb = read_checkpoint(dir.path(b + "/checkpoint.bin"), 10000, 1);
    EXPECT_TRUE(ca.state.x == cb.state.x) << a << " " << b;
    EXPECT_TRUE(ca.state.velocity == cb.state.velocity) << a << " " << b;
    EXPECT_EQ(ca.state.regularization, cb.state.regularization);
    EXPECT_EQ(without_timing(slurp(dir.path(a + "/result.json"))),
              without_timing(slurp(dir.path(b + "/result.json"))));
    EXPECT_EQ(without_seconds(slurp(dir.path(a + "/convergence.csv"))),
              without_seconds(slurp(dir.path(b + "/convergence.csv"))));
  }
  test::TempDir dir;
};

TEST_P(Reproducible, SameBitsTwiceAndOnEitherThreadCount) {
  const std::string one = run("one", 1), two = run("two", 2), again = run("again", 2);
  expect_same(two, again);
  expect_same(one, two);
}

TEST_P(Reproducible, ResultRecordsVersionSceneHashAndThreads) {
  const std::string json = slurp(dir.path(run("out", 2) + "/result.json"));
  EXPECT_NE(json.find("\"fabform_version\": \"" FABFORM_VERSION "\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"scene_sha256\": \"" + sha256_of_file(test::source_path("scenes/dome.toml")) + "\""),
            std::string::npos) << json;
  EXPECT_NE(json.find("\"threads\": 2"), std::string::npos) << json;
}

// Friction, a clamp and vacuum add their own loops over the nodes (the lagged friction's forces
// among them): the vacuum scene at 95 × 95 divisions (9 216 nodes), newton stopped at its cap
// with some 1 300 nodes held on the mold by friction.
TEST(ReproducibleForming, VacuumWithFrictionOnEitherThreadCount) {
  test::TempDir dir;
  const auto run = [&](int threads) {
    const std::string out = "t" + std::to_string(threads);
    const test::Outcome o = test::run_fabform(dir, "run '" + test::source_path("scenes/vacuum.toml") + "' --out " + out +
                                                       " --quiet --set fabric.divisions=[95,95] --max-iter 12 --threads " +
                                                       std::to_string(threads));
    EXPECT_EQ(o.status, 3) << o.err;
    return out;
  };
  const std::string one = run(1), two = run(2);
  EXPECT_TRUE(slurp(dir.path(one + "/fabric.obj")) == slurp(dir.path(two + "/fabric.obj")));
  EXPECT_EQ(without_timing(slurp(dir.path(one + "/result.json"))), without_timing(slurp(dir.path(two + "/result.json"))));
}

INSTANTIATE_TEST_SUITE_P(EverySolver, Reproducible,
                         ::testing::Values(Case{"relax", 10}, Case{"dynamic", 100}, Case{"newton", 4}),
                         [](const auto& case_info) { return std::string(case_info.param.solver); });

}  // namespace
}  // namespace fabform::reproducibility_test
