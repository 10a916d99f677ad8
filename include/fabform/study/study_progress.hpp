#pragma once
// A study's progress line on standard error: cases done, running and failed of all, and the
// time left, estimated from the pace so far. On a terminal one line rewritten; into a file, a
// line whenever a count changes.
#include <chrono>
#include <cstdio>

namespace fabform {

class StudyProgress {
 public:
  /// `cases` to run now, of `total`; the others were finished before (a resumed study).
  StudyProgress(std::FILE* out, int cases, int total, bool quiet);

  void update(int done, int running, int failed);
  void finish();

 private:
  std::FILE* out_;
  int cases_;
  int total_;
  bool quiet_;
  bool terminal_;
  int last_[3] = {-1, -1, -1};
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point shown_{};
};

}  // namespace fabform
