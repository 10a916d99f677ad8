#pragma once
// Shows a run's progress: on a terminal one line rewritten in place a few times a second; in a
// log file a line every few seconds, so long runs do not flood it.
#include <chrono>
#include <cstdio>

#include "fabform/solver/summary.hpp"

namespace fabform {

class Progress {
 public:
  explicit Progress(std::FILE* stream);
  void update(const IterationRecord& record);
  /// Prints the last record seen, whatever the interval, and ends the line.
  void finish();

 private:
  void print(const IterationRecord& record);

  std::FILE* stream_;
  bool terminal_;
  std::chrono::steady_clock::time_point last_print_;
  IterationRecord last_{};
  IterationRecord previous_printed_{};
  bool printed_any_ = false;
};

}  // namespace fabform
