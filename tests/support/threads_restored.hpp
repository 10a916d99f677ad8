#pragma once
// A test that changes the thread count puts the count it found back when it ends, however it
// ends (an ASSERT returns early), so the tests after it in the same process run as they would
// alone.
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

}  // namespace fabform::test
