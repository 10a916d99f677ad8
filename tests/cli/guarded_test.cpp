// Every command reports what it throws on one line, with the exit status of its kind: bad input,
// the system's refusal, or a bug of fabform's own.
#include "cli/guarded.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>

#include "cli/commands.hpp"
#include "fabform/error.hpp"

namespace fabform::cli::guarded_test {
namespace {

struct Reported {
  int status;
  std::string err;
};

template <class Throw>
Reported reported(Throw throw_it) {
  testing::internal::CaptureStderr();
  const int status = guarded([&]() -> int {
    throw_it();
    return kExitDone;  // not reached: every caller throws
  });
  return {status, testing::internal::GetCapturedStderr()};
}

TEST(Guarded, TheCommandsOwnStatusPassesThrough) {
  EXPECT_EQ(guarded([] { return kExitNotConverged; }), kExitNotConverged);
}

TEST(Guarded, BadInputIsTwo) {
  const Reported r = reported([] { throw InputError({"scene.toml", 4, "fabric.divisions"}, "must be positive"); });
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "fabform: error: scene.toml:4: fabric.divisions: must be positive\n");
  EXPECT_EQ(reported([] { throw std::invalid_argument("unknown solver 'fast'"); }).status, 2);
}

TEST(Guarded, WhatTheSystemRefusesIsFiveWithItsReason) {
  const Reported r = reported([] { throw SystemError("out/result.json", "write", system_reason(ENOSPC)); });
  EXPECT_EQ(r.status, 5);
  EXPECT_EQ(r.err, "fabform: error: out/result.json: cannot write (No space left on device)\n");
  EXPECT_EQ(reported([] { throw std::bad_alloc(); }).status, 5);
  EXPECT_EQ(reported([] { throw std::system_error(EACCES, std::generic_category(), "out"); }).status, 5);
}

TEST(Guarded, AnythingElseIsABugSaidToBeOne) {
  for (const Reported& r : {reported([] { throw std::logic_error("an index past the end"); }),
                            reported([] { throw 42; })}) {
    EXPECT_EQ(r.status, 70);
    EXPECT_NE(r.err.find("internal error, a bug in fabform"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace fabform::cli::guarded_test
