#pragma once
// Watches a run iteration by iteration: shows progress, writes a
// checkpoint every K iterations or M minutes (the scene's [output] settings), and keeps the
// last state without a NaN or Inf, which is what a run that breaks numerically writes.
#include <chrono>
#include <functional>

#include "fabform/output/progress.hpp"
#include "fabform/scene/scene.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

/// Writes a results folder for a state and the summary so far.
using Publisher = std::function<void(const SolverState&, const Summary&)>;

class RunMonitor {
 public:
  /// Watches `state` as the solver changes it; `so_far` is the summary a resumed run goes on
  /// from (empty for a fresh run), `progress` null for a quiet run.
  RunMonitor(const SolverState& state, Summary so_far, const CheckpointSpec& checkpoints,
             Publisher publish, Progress* progress);

  /// The solver's observer.
  void observe(const IterationRecord& record);
  /// Writes a checkpoint now (a load step has ended: resuming goes on from the next).
  void checkpoint();

  /// The newest state kept whose residual was finite, and its iteration.
  const SolverState& last_good_state() const { return last_good_; }
  int last_good_iteration() const { return last_good_iteration_; }

 private:
  using Clock = std::chrono::steady_clock;
  bool checkpoint_due() const;
  void keep_good_state(const IterationRecord& record);

  const SolverState& state_;
  Summary so_far_;
  CheckpointSpec checkpoints_;
  Publisher publish_;
  Progress* progress_;
  int iterations_since_checkpoint_ = 0;
  Clock::time_point last_checkpoint_time_ = Clock::now();
  SolverState last_good_;
  int last_good_iteration_ = -1;
  Clock::time_point last_copy_end_ = Clock::now();
  double last_copy_seconds_ = 0.0;
};

}  // namespace fabform
