#pragma once
// A test that changes the thread count puts the count it found back when it ends, however it
// ends (an ASSERT returns early), so the tests after it in the same process run as they would
// alone.
#include <initializer_list>

#include <gtest/gtest.h>

#include "fabform/thread_count.hpp"

namespace fabform::test {

class ThreadsRestored {
 public:
  ThreadsRestored() : before_(threads_in_use()) {}
  ~ThreadsRestored() { use_threads(before_); }
  ThreadsRestored(const ThreadsRestored&) = delete;
  ThreadsRestored& operator=(const ThreadsRestored&) = delete;

 private:
  int before_;
};

/// Runs `check` on each thread count in turn, each run traced with its count; the count in use
/// is put back after.
template <class Check>
void on_thread_counts(std::initializer_list<int> counts, Check check) {
  const ThreadsRestored restored;
  for (const int threads : counts) {
    SCOPED_TRACE(testing::Message() << threads << " thread(s)");
    use_threads(threads);
    check();
  }
}

}  // namespace fabform::test
