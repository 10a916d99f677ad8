#include "fabform/output/progress.hpp"

#include <unistd.h>

#include <cmath>

namespace fabform {

Progress::Progress(std::FILE* stream)
    : stream_(stream), terminal_(isatty(fileno(stream)) != 0), last_print_() {}

void Progress::update(const IterationRecord& record) {
  last_ = record;
  const auto now = std::chrono::steady_clock::now();
  const auto interval = terminal_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(10000);
  if (printed_any_ && now - last_print_ < interval) return;
  last_print_ = now;
  print(record);
}

void Progress::print(const IterationRecord& r) {
  // Rate: decades of residual gained per 1000 iterations since the last line.
  double rate = 0.0;
  const int steps = r.iteration - previous_printed_.iteration;
  if (printed_any_ && steps > 0 && r.residual_N > 0.0 && previous_printed_.residual_N > 0.0)
    rate = 1000.0 * std::log10(previous_printed_.residual_N / r.residual_N) / steps;
  std::fprintf(stream_, "%siteration %8d  residual %.3e N  rate %+.2f decades/1000 it  contact %d  %.1f s%s",
               terminal_ ? "\r" : "", r.iteration, r.residual_N, rate, r.contact_nodes, r.seconds,
               terminal_ ? "   " : "\n");
  std::fflush(stream_);
  previous_printed_ = r;
  printed_any_ = true;
}

void Progress::finish() {
  if (!printed_any_ || last_.iteration != previous_printed_.iteration) print(last_);
  if (terminal_) std::fputc('\n', stream_);
  std::fflush(stream_);
}

}  // namespace fabform
