// Interrupt and resume on the real binary: a run of the shipped mold scene is stopped by SIGINT,
// SIGTERM or SIGKILL after its first checkpoint, resumed with `fabform run --resume DIR`, and
// must end where an uninterrupted run ends: same iterations, same positions to the last digit
// written (fabric.obj's 12 significant digits: within 1e-13 m), same history.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>
#include <vector>

#include "support/cli.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::run_resume_test {
namespace {

namespace fs = std::filesystem;
using test::slurp;

// The real mold at 30 × 30 divisions to 1e-3 N: about 700 sweeps (1.7 s), long enough to be
// interrupted after a checkpoint every 100 of them, short enough for a test.
std::vector<std::string> mold_run(const std::string& out, const std::string& checkpoint_setting) {
  return {"run", test::source_path("scenes/mold.toml"), "--out", out, "--quiet",
          "--set", "fabric.divisions=[30,30]", "--tol", "1e-3", "--set", checkpoint_setting};
}

std::string field(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return "";
  const auto start = at + key.size() + 4;
  return json.substr(start, json.find_first_of(",\n", start) - start);
}

// Every value of `key` in the text, in order (a step's figures, one per step).
std::vector<std::string> every_field(const std::string& json, const std::string& key) {
  std::vector<std::string> values;
  for (auto at = json.find("\"" + key + "\": "); at != std::string::npos; at = json.find("\"" + key + "\": ", at + 1)) {
    const auto start = at + key.size() + 4;
    values.push_back(json.substr(start, json.find_first_of(",\n", start) - start));
  }
  return values;
}

bool wait_for_file(const std::string& path, std::chrono::seconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (!fs::exists(path)) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

struct Kill {
  const char* name;
  int signal;
  int expected_status;  // of the interrupted run
  const char* checkpoint_setting;
};

class RunResume : public ::testing::TestWithParam<Kill> {
 protected:
  static void SetUpTestSuite() {
    reference_ = new test::TempDir;
    const pid_t pid = test::start_fabform(*reference_, mold_run("out", "output.checkpoint_every_iterations=0"));
    ASSERT_EQ(test::wait_for_exit(pid), 0) << slurp(reference_->path("stderr.txt"));
  }
  static void TearDownTestSuite() {
    delete reference_;
    reference_ = nullptr;
  }
  static test::TempDir* reference_;
  test::TempDir dir;
};
test::TempDir* RunResume::reference_ = nullptr;

TEST_P(RunResume, EndsWhereTheUninterruptedRunEnds) {
  const Kill& kill_with = GetParam();
  const pid_t pid = test::start_fabform(dir, mold_run("out", kill_with.checkpoint_setting));
  ASSERT_TRUE(wait_for_file(dir.path("out/checkpoint.bin"), std::chrono::seconds(120)))
      << slurp(dir.path("stderr.txt"));
  kill(pid, kill_with.signal);
  ASSERT_EQ(test::wait_for_exit(pid), kill_with.expected_status) << slurp(dir.path("stderr.txt"));

  const std::string stopped = slurp(dir.path("out/result.json"));
  const std::string termination = field(stopped, "termination");
  EXPECT_EQ(termination, kill_with.signal == SIGKILL ? "\"running\"" : "\"interrupted\"") << stopped;
  EXPECT_EQ(field(stopped, "converged"), "false");
  const int stopped_at = std::stoi(field(stopped, "iterations"));

  const test::Outcome resumed = test::run_fabform(dir, "run --resume out --quiet");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("resumed after iteration " + std::to_string(stopped_at)), std::string::npos)
      << resumed.err;

  const std::string done = slurp(dir.path("out/result.json"));
  const std::string reference = slurp(reference_->path("out/result.json"));
  EXPECT_EQ(field(done, "termination"), "\"converged\"");
  EXPECT_NEAR(std::stoi(field(done, "iterations")), std::stoi(field(reference, "iterations")), 1);
  EXPECT_EQ(field(done, "residual_N"), field(reference, "residual_N"));
  EXPECT_EQ(slurp(dir.path("out/fabric.obj")), slurp(reference_->path("out/fabric.obj")));
  EXPECT_EQ(test::line_count(slurp(dir.path("out/convergence.csv"))),
            test::line_count(slurp(reference_->path("out/convergence.csv"))));
  EXPECT_FALSE(fs::exists(dir.path("out/checkpoint.bin"))) << "a converged run keeps no checkpoint";
  for (const auto& entry : fs::directory_iterator(dir.root()))
    EXPECT_EQ(entry.path().filename().string().find(".out.fabform"), std::string::npos)
        << "left behind: " << entry.path();
}

INSTANTIATE_TEST_SUITE_P(
    Signals, RunResume,
    ::testing::Values(Kill{"Sigint", SIGINT, 128 + SIGINT, "output.checkpoint_every_iterations=100"},
                      Kill{"Sigterm", SIGTERM, 128 + SIGTERM, "output.checkpoint_every_minutes=0.002"},
                      Kill{"Sigkill", SIGKILL, -SIGKILL, "output.checkpoint_every_iterations=100"}),
    [](const auto& case_info) { return std::string(case_info.param.name); });

// A run in load steps killed once its second step is written goes on from its checkpoint and
// ends as the uninterrupted run ends: the same fabric, every step's files and figures.
TEST(RunResumeInSteps, EndsWhereTheUninterruptedRunEnds) {
  test::TempDir dir;
  const auto cup_run = [&](const std::string& out) {
    return std::vector<std::string>{"run", test::source_path("scenes/cup.toml"), "--out", out, "--quiet",
                                    "--set", "body.0.path.steps=24"};
  };
  ASSERT_EQ(test::wait_for_exit(test::start_fabform(dir, cup_run("reference"))), 0) << slurp(dir.path("stderr.txt"));
  const pid_t pid = test::start_fabform(dir, cup_run("out"));
  ASSERT_TRUE(wait_for_file(dir.path("out/fabric_step_002.vtp"), std::chrono::seconds(120)));
  kill(pid, SIGKILL);
  const int killed = test::wait_for_exit(pid);
  if (killed == 0) GTEST_SKIP() << "the run finished before it could be killed";
  ASSERT_EQ(killed, -SIGKILL);
  EXPECT_EQ(field(slurp(dir.path("out/result.json")), "termination"), "\"running\"");

  const test::Outcome resumed = test::run_fabform(dir, "run --resume out --quiet");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_EQ(slurp(dir.path("out/fabric.obj")), slurp(dir.path("reference/fabric.obj")));
  EXPECT_EQ(slurp(dir.path("out/fabric_steps.pvd")), slurp(dir.path("reference/fabric_steps.pvd")));
  for (const char* file : {"fabric_step_001.vtp", "fabric_step_002.vtp", "fabric_step_013.vtp", "fabric_step_024.vtp",
                           "bodies_step_024.vtp"})
    EXPECT_EQ(slurp(dir.path(std::string("out/") + file)), slurp(dir.path(std::string("reference/") + file))) << file;
  const std::string done = slurp(dir.path("out/result.json"));
  const std::string reference = slurp(dir.path("reference/result.json"));
  EXPECT_EQ(field(done, "iterations"), field(reference, "iterations"));
  EXPECT_EQ(field(done, "draw_in_max_m"), field(reference, "draw_in_max_m"));
  // Every step's figures but its seconds.
  for (const char* key : {"step", "iterations", "residual_N", "contact_nodes", "max_warp_strain", "draw_in_max_m"})
    EXPECT_EQ(every_field(done, key), every_field(reference, key)) << key;
  EXPECT_EQ(every_field(done, "step").size(), 24u);
}

// What cannot be resumed says why, exits 2 and leaves the folder as it was.
class ResumeRefusal : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("table.csv", "strain,tension_N_per_m\n0,0\n1,500\n");
    dir.write("scene.toml",
              "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [10, 10]\n"
              "warp = \"table.csv\"\nweft = \"table.csv\"\n"
              "[[constraint]]\nnodes = \"perimeter\"\n"
              "[initial]\nshape = \"bump\"\nheight_m = 0.02\n"
              "[solver]\ntolerance_N = 1e-9\n");
  }
  std::string refusal(const std::string& arguments) {
    const std::string before = slurp(dir.path("out/result.json"));
    const test::Outcome o = test::run_fabform(dir, arguments);
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_EQ(test::error_line_count(o.err), 1) << o.err;
    EXPECT_EQ(slurp(dir.path("out/result.json")), before);
    return o.err;
  }
  test::TempDir dir;
};

TEST_F(ResumeRefusal, ChangedInputIsNamed) {
  ASSERT_EQ(test::run_fabform(dir, "run scene.toml --out out --max-iter 3").status, 3);
  dir.write("table.csv", "strain,tension_N_per_m\n0,0\n1,600\n");
  const std::string err = refusal("run --resume out");
  EXPECT_NE(err.find("cannot resume: the warp file"), std::string::npos) << err;
  EXPECT_NE(err.find("has changed since"), std::string::npos) << err;
}

TEST_F(ResumeRefusal, ConvergedRunHasNoCheckpoint) {
  ASSERT_EQ(test::run_fabform(dir, "run scene.toml --out out --tol 1e-3").status, 0);
  EXPECT_NE(refusal("run --resume out").find("no checkpoint to resume from"), std::string::npos);
}

TEST_F(ResumeRefusal, FolderThatIsNoRunsResults) {
  fs::create_directories(dir.path("out"));
  EXPECT_NE(refusal("run --resume out").find("result.json"), std::string::npos);
}

TEST_F(ResumeRefusal, ResumeTakesNoSceneOrOverrides) {
  ASSERT_EQ(test::run_fabform(dir, "run scene.toml --out out --max-iter 3").status, 3);
  for (const char* arguments : {"run scene.toml --resume out", "run --resume out --tol 1e-3",
                                "run --resume out --out elsewhere", "run --resume"})
    EXPECT_NE(refusal(arguments).find("--resume"), std::string::npos) << arguments;
}

// A run stopped at its cap can be resumed: with the same cap it stops again at once, and says so.
TEST_F(ResumeRefusal, RunAtItsCapResumesToItsCap) {
  ASSERT_EQ(test::run_fabform(dir, "run scene.toml --out out --max-iter 3").status, 3);
  const test::Outcome o = test::run_fabform(dir, "run --resume out");
  EXPECT_EQ(o.status, 3) << o.err;
  EXPECT_EQ(field(slurp(dir.path("out/result.json")), "iterations"), "3");
}

}  // namespace
}  // namespace fabform::run_resume_test
