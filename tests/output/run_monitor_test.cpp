// The run monitor writes checkpoints on the scene's schedule with the history so far, goes on
// counting from a resumed run's iteration, and keeps the last state that was good.
#include "fabform/output/run_monitor.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "fabform/error.hpp"

namespace fabform::run_monitor_test {
namespace {

struct Published {
  std::vector<Eigen::Vector3d> x;
  Summary summary;
};

class RunMonitorTest : public ::testing::Test {
 protected:
  RunMonitorTest() { state.x = {Eigen::Vector3d::Zero()}, state.contact.resize(1); }
  RunMonitor monitor(const CheckpointSpec& spec, Summary so_far = {}) {
    so_far = begin_summary("relax", 1e-6, std::move(so_far));
    return RunMonitor(state, so_far, spec,
                      [this](const SolverState& s, const Summary& summary) { published.push_back({s.x, summary}); },
                      nullptr);
  }
  // Iteration k moves the node to x = k and reports a residual of 1/(k+1) N.
  void iterate(RunMonitor& m, int k, double residual = 0.0) {
    state.x[0].x() = k;
    m.observe({k, residual == 0.0 ? 1.0 / (k + 1) : residual, 0.1 * k, 0});
  }
  SolverState state;
  std::vector<Published> published;
};

TEST_F(RunMonitorTest, CheckpointsEveryKIterationsWithTheHistorySoFar) {
  RunMonitor m = monitor({3, 0.0});
  for (int k = 0; k <= 10; ++k) iterate(m, k);
  ASSERT_EQ(published.size(), 3u);  // after iterations 3, 6, 9
  for (std::size_t c = 0; c < published.size(); ++c) {
    const int at = 3 * static_cast<int>(c + 1);
    const Summary& s = published[c].summary;
    EXPECT_EQ(s.termination, Termination::running);
    EXPECT_EQ(s.iterations, at);
    EXPECT_EQ(s.solver, "relax");
    EXPECT_EQ(s.history.size(), static_cast<std::size_t>(at + 1));
    EXPECT_EQ(s.history.back().residual_N, 1.0 / (at + 1));
    EXPECT_EQ(published[c].x[0].x(), at) << "the state of that iteration";
    EXPECT_NE(s.message.find("checkpoint after iteration " + std::to_string(at)), std::string::npos);
  }
}

// A checkpoint the disk cannot take does not end the run: the next one is tried when due.
TEST_F(RunMonitorTest, ACheckpointThatCannotBeWrittenDoesNotStopTheRun) {
  int attempts = 0;
  RunMonitor m(state, begin_summary("relax", 1e-6, {}), {2, 0.0},
               [&](const SolverState&, const Summary&) {
                 ++attempts;
                 if (attempts == 1) throw SystemError("out/result.json", "write", system_reason(ENOSPC));
                 published.push_back({state.x, {}});
               },
               nullptr);
  for (int k = 0; k <= 4; ++k) EXPECT_NO_THROW(iterate(m, k));
  EXPECT_EQ(attempts, 2) << "after iterations 2 and 4";
  ASSERT_EQ(published.size(), 1u);
  EXPECT_EQ(published[0].x[0].x(), 4);
}

TEST_F(RunMonitorTest, CheckpointsEveryMMinutes) {
  RunMonitor m = monitor({0, 1e-5});  // 0.6 ms
  iterate(m, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  iterate(m, 1);
  ASSERT_EQ(published.size(), 1u);
  EXPECT_EQ(published[0].summary.iterations, 1);
}

TEST_F(RunMonitorTest, NeitherScheduleMeansNoCheckpoints) {
  RunMonitor m = monitor({0, 0.0});
  for (int k = 0; k <= 100; ++k) iterate(m, k);
  EXPECT_TRUE(published.empty());
}

// A resumed run counts K from where it was resumed, and its first record (the checkpoint's
// state measured again) replaces the history's last instead of repeating it.
TEST_F(RunMonitorTest, ResumedRunGoesOnFromItsCheckpoint) {
  Summary so_far;
  so_far.solver = "relax";
  so_far.iterations = 5;
  for (int k = 0; k <= 5; ++k) so_far.history.push_back({k, 1.0 / (k + 1), 0.1 * k, 0});
  RunMonitor m = monitor({2, 0.0}, so_far);
  for (int k = 5; k <= 7; ++k) iterate(m, k);
  ASSERT_EQ(published.size(), 1u);
  EXPECT_EQ(published[0].summary.iterations, 7);
  ASSERT_EQ(published[0].summary.history.size(), 8u);
  for (int k = 0; k <= 7; ++k) EXPECT_EQ(published[0].summary.history[static_cast<std::size_t>(k)].iteration, k);
}

// Spaced a millisecond apart, every good state is kept (copies of one node take far less than a
// twentieth of that); the broken one is not, and is not checkpointed.
TEST_F(RunMonitorTest, KeepsTheLastGoodState) {
  RunMonitor m = monitor({1, 0.0});
  for (int k = 0; k <= 3; ++k) {
    iterate(m, k);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  const std::size_t checkpoints = published.size();
  state.x[0].x() = std::nan("");
  m.observe({4, std::nan(""), 0.4, 0});
  EXPECT_EQ(m.last_good_iteration(), 3);
  EXPECT_EQ(m.last_good_state().x[0].x(), 3.0);
  EXPECT_EQ(published.size(), checkpoints);
}

TEST_F(RunMonitorTest, NoGoodStateBeforeTheFirstFiniteResidual) {
  RunMonitor m = monitor({0, 0.0});
  m.observe({0, std::numeric_limits<double>::infinity(), 0.0, 0});
  EXPECT_EQ(m.last_good_iteration(), -1);
}

}  // namespace
}  // namespace fabform::run_monitor_test
