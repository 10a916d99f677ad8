#pragma once
// Work shared among OpenMP threads must not throw out of its parallel region (the process would
// end): each exception is caught where it is thrown, kept, and rethrown once the region is over.
#include <algorithm>
#include <atomic>
#include <exception>

#include "fabform/thread_count.hpp"

namespace fabform {

/// The first exception caught on any thread of a parallel loop.
class ParallelFailure {
 public:
  /// In a catch block, on any thread.
  void capture() noexcept {
#pragma omp critical(fabform_parallel_failure)
    if (!first_) first_ = std::current_exception();
    caught_.store(true, std::memory_order_relaxed);
  }
  /// Whether one was caught: work left after a failure may be skipped.
  bool caught() const noexcept { return caught_.load(std::memory_order_relaxed); }
  /// After the region.
  void rethrow() const {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  std::exception_ptr first_;
  std::atomic<bool> caught_{false};
};

/// work(0) and work(1), each on its own thread where the run has two; an exception in either is
/// rethrown after both, side 0's first.
template <class Work>
void on_each_side(Work&& work) {
  std::exception_ptr failed[2];
  const int threads = std::min(2, threads_in_use());  // no more than the run asked for
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (int s = 0; s < 2; ++s) {
    try {
      work(s);
    } catch (...) {
      failed[s] = std::current_exception();
    }
  }
  for (const auto& f : failed)
    if (f) std::rethrow_exception(f);
}

}  // namespace fabform
