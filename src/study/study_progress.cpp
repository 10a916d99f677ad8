#include "fabform/study/study_progress.hpp"

#include <unistd.h>

#include <cmath>
#include <string>

namespace fabform {
namespace {

std::string duration_text(double seconds) {
  const long s = std::lround(seconds);
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, s / 60 % 60);
  else if (s >= 60) std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%lds", s);
  return text;
}

}  // namespace

StudyProgress::StudyProgress(std::FILE* out, int cases, int total, bool quiet)
    : out_(out), cases_(cases), total_(total), quiet_(quiet), terminal_(isatty(fileno(out)) != 0) {}

void StudyProgress::update(int done, int running, int failed) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool changed = done != last_[0] || running != last_[1] || failed != last_[2];
  // A terminal's line ticks its clock once a second; a file gets a line per case done.
  if (terminal_ ? !changed && now - shown_ < std::chrono::seconds(1) : done == last_[0]) return;
  last_[0] = done, last_[1] = running, last_[2] = failed;
  shown_ = now;
  const double elapsed = std::chrono::duration<double>(now - started_).count();
  const std::string left = done > 0 ? "~" + duration_text(elapsed / done * (cases_ - done)) : "?";
  const int before = total_ - cases_;
  std::fprintf(out_, "%sstudy: %d/%d cases done, %d running, %d failed, %s elapsed, time left %s%s",
               terminal_ ? "\r" : "", before + done, total_, running, failed, duration_text(elapsed).c_str(),
               left.c_str(), terminal_ ? "\x1b[K" : "\n");
  std::fflush(out_);
}

void StudyProgress::finish() {
  if (!quiet_ && terminal_) std::fputc('\n', out_);
}

}  // namespace fabform
