// checkpoint.bin: every bit of a state and summary comes back, and a damaged, truncated or
// foreign file is refused with a message naming it, before anything large is allocated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "fabform/error.hpp"
#include "fabform/output/checkpoint.hpp"
#include "support/temp_dir.hpp"

namespace fabform::checkpoint_test {
namespace {

SolverState sample_state(bool with_velocity) {
  SolverState s;
  for (int k = 0; k < 5; ++k) {
    s.x.emplace_back(0.1 * k + 1e-17, std::nextafter(1.0 / 3.0, 1.0), -k * 1e-300);
    NodeContact c;
    if (k % 2) c.body = 1, c.normal = Eigen::Vector3d(0.6, 0.0, 0.8);
    s.contact.push_back(c);
    if (with_velocity) s.velocity.emplace_back(1e-9 * k, -2.5, 3.0);
  }
  s.regularization = 1.234e-7;
  return s;
}

Summary sample_summary() {
  Summary s;
  s.solver = "dynamic";
  s.termination = Termination::interrupted;
  s.message = "interrupted";
  s.iterations = 2;
  s.residual_N = 0.5;
  s.tolerance_N = 1e-6;
  s.seconds = 1.25;
  s.worst_node = 3;
  s.history = {{0, 2.0, 0.0, 0, 1}, {1, 1.0, 0.5, 2, 1}, {0, 0.5, 1.25, 3, 2}};  // two load steps
  return s;
}

Checkpoint round_trip(const std::string& bytes, int nodes = 5, int bodies = 2) {
  static const test::TempDir dir;  // one for the many cases below
  return read_checkpoint(dir.write("checkpoint.bin", bytes), nodes, bodies);
}

std::string error_of(const std::string& bytes, int nodes = 5, int bodies = 2) {
  try {
    round_trip(bytes, nodes, bodies);
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("checkpoint.bin"), std::string::npos) << error.what();
    return error.what();
  }
  return "no error";
}

TEST(Checkpoint, RoundTripIsBitExact) {
  for (const bool velocity : {false, true}) {
    const SolverState state = sample_state(velocity);
    const Checkpoint c = round_trip(checkpoint_bytes(state, sample_summary()));
    ASSERT_EQ(c.state.x.size(), state.x.size());
    for (std::size_t i = 0; i < state.x.size(); ++i) {
      EXPECT_EQ(std::memcmp(c.state.x[i].data(), state.x[i].data(), sizeof(double) * 3), 0);
      EXPECT_EQ(c.state.contact[i].body, state.contact[i].body);
      EXPECT_EQ(c.state.contact[i].normal, state.contact[i].normal);
      EXPECT_EQ(c.state.contact[i].anchor, state.contact[i].anchor);
    }
    EXPECT_EQ(c.state.velocity, state.velocity);
    EXPECT_EQ(c.state.regularization, state.regularization);
    const Summary expected = sample_summary();
    EXPECT_EQ(c.summary.solver, expected.solver);
    EXPECT_EQ(c.summary.termination, expected.termination);
    EXPECT_EQ(c.summary.iterations, expected.iterations);
    EXPECT_EQ(c.summary.seconds, expected.seconds);
    ASSERT_EQ(c.summary.history.size(), expected.history.size());
    EXPECT_EQ(c.summary.history.back().residual_N, 0.5);
    EXPECT_EQ(c.summary.history.back().contact_nodes, 3);
    EXPECT_EQ(c.summary.history.back().step, 2);
  }
}

TEST(Checkpoint, EveryTruncationIsRefused) {
  const std::string bytes = checkpoint_bytes(sample_state(true), sample_summary());
  for (std::size_t size = 0; size < bytes.size(); ++size)
    EXPECT_NE(error_of(bytes.substr(0, size)), "no error") << "accepted " << size << " of " << bytes.size();
}

TEST(Checkpoint, EveryFlippedByteIsRefused) {
  const std::string bytes = checkpoint_bytes(sample_state(false), sample_summary());
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x40);
    EXPECT_NE(error_of(damaged), "no error") << "accepted a change at byte " << at;
  }
}

TEST(Checkpoint, AnotherModelsCheckpointIsRefused) {
  const std::string bytes = checkpoint_bytes(sample_state(false), sample_summary());
  EXPECT_NE(error_of(bytes, 6).find("made for 5 nodes; the scene has 6"), std::string::npos);
  EXPECT_NE(error_of(bytes, 5, 1).find("rests on body 1"), std::string::npos);
  EXPECT_NE(error_of("not a checkpoint at all").find("not a fabform checkpoint"), std::string::npos);
  EXPECT_NE(error_of("").find("not a fabform checkpoint"), std::string::npos);
}

// A checkpoint of the format before valleys (NodeContact::crease) is named as such, not as foreign.
TEST(Checkpoint, EarlierFormatIsNamed) {
  std::string bytes = checkpoint_bytes(sample_state(false), sample_summary());
  bytes.replace(0, std::string("fabform checkpoint 4").size(), "fabform checkpoint 3");
  const std::string error = error_of(bytes);
  EXPECT_NE(error.find("another checkpoint format (fabform checkpoint 3; this fabform reads fabform checkpoint 4)"),
            std::string::npos)
      << error;
}

TEST(Checkpoint, MissingFileSaysThereIsNothingToResume) {
  try {
    read_checkpoint("/nonexistent/checkpoint.bin", 5, 2);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("no checkpoint to resume from"), std::string::npos);
  }
}

}  // namespace
}  // namespace fabform::checkpoint_test
