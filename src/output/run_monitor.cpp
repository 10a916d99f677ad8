#include "fabform/output/run_monitor.hpp"

#include <cmath>
#include <cstdio>
#include <system_error>
#include <utility>

#include "fabform/error.hpp"

namespace fabform {
namespace {

// Copying the state after every iteration would cost a fast solver (dynamic steps, small
// grids) a good share of its time; a copy is taken once the time since the last is this many
// times what the last copy took, bounding the cost near 5 %.
constexpr double kCopyIntervalFactor = 20.0;

void warn_unwritten(const std::exception& error) {
  std::fprintf(stderr, "\nfabform: warning: checkpoint not written: %s; the last one written is kept\n", error.what());
}

}  // namespace

RunMonitor::RunMonitor(const SolverState& state, Summary so_far, const CheckpointSpec& checkpoints,
                       Publisher publish, Progress* progress)
    : state_(state),
      so_far_(std::move(so_far)),
      checkpoints_(checkpoints),
      publish_(std::move(publish)),
      progress_(progress) {}

void RunMonitor::observe(const IterationRecord& record) {
  if (progress_) progress_->update(record);
  if (!std::isfinite(record.residual_N)) return;
  keep_good_state(record);
  // A resumed run, or a load step's solver, re-measures the state it goes on from.
  if (!so_far_.history.empty() && so_far_.history.back().iteration == record.iteration &&
      so_far_.history.back().step == record.step) {
    so_far_.history.back() = record;
  } else {
    so_far_.history.push_back(record);
    if (record.iteration > 0) ++iterations_since_checkpoint_;  // iteration 0 measures a start
  }
  if (!record.inside_cut && checkpoint_due()) checkpoint();
}

void RunMonitor::checkpoint() {
  if (so_far_.history.empty()) return;
  const IterationRecord& record = so_far_.history.back();
  Summary snapshot = so_far_;
  snapshot.termination = Termination::running;
  snapshot.iterations = total_iterations(so_far_.history);
  snapshot.residual_N = record.residual_N;
  snapshot.seconds = record.seconds;
  snapshot.message = stop_message(snapshot);
  // A checkpoint that cannot be written (a full disk) must not end the run: the last one written
  // is kept, and the next is tried when it is due.
  try {
    publish_(state_, snapshot);
  } catch (const SystemError& error) {
    warn_unwritten(error);
  } catch (const std::system_error& error) {  // a file system call of the results folder's
    warn_unwritten(error);
  }
  iterations_since_checkpoint_ = 0;
  last_checkpoint_time_ = Clock::now();
}

bool RunMonitor::checkpoint_due() const {
  const int every = checkpoints_.every_iterations;
  if (every > 0 && iterations_since_checkpoint_ >= every) return true;
  const double minutes = std::chrono::duration<double>(Clock::now() - last_checkpoint_time_).count() / 60.0;
  return checkpoints_.every_minutes > 0.0 && minutes >= checkpoints_.every_minutes;
}

void RunMonitor::keep_good_state(const IterationRecord& record) {
  const auto now = Clock::now();
  if (last_good_iteration_ >= 0 &&
      std::chrono::duration<double>(now - last_copy_end_).count() < kCopyIntervalFactor * last_copy_seconds_)
    return;
  last_good_ = state_;
  last_good_iteration_ = record.iteration;
  last_copy_end_ = Clock::now();
  last_copy_seconds_ = std::chrono::duration<double>(last_copy_end_ - now).count();
}

}  // namespace fabform
