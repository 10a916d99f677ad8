// The parallel loops' thread count: what use_threads sets, threads_in_use reads back, so a test
// that changes it can leave it as it found it.
#include "fabform/thread_count.hpp"

#include <gtest/gtest.h>

namespace fabform::thread_count_test {
namespace {

TEST(ThreadCount, ThreadsInUseReadsWhatUseThreadsSet) {
  const int before = threads_in_use();
  EXPECT_GE(before, 1);
  use_threads(3);
  EXPECT_EQ(threads_in_use(), 3);
  use_threads(before);
  EXPECT_EQ(threads_in_use(), before);
}

}  // namespace
}  // namespace fabform::thread_count_test
