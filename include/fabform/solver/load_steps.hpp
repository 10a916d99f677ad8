#pragma once
// Forming as it happens: the bodies travel along their paths (tool_path.hpp) in K load steps,
// and each step is solved to the tolerance from the rest of the one before, so that the
// history friction depends on is kept (where each node landed, how far it has slid).
// Step k moves each travelling body from its pose k−1 to its pose k and carries the fabric
// with it: a node resting on the body moves with it (with its friction anchor), and a node the
// body now overlaps is put on its surface where it is closest. The solver then finds the
// step's rest. Records are numbered within their step (IterationRecord::step), so a run's
// history is every step's convergence in turn.
//
// A step that does not converge (its iteration cap reached, or newton's line search stalled)
// is cut, as Abaqus cuts an increment: the state and the bodies go back to where the step (or
// the part of it that failed) began, and the part is solved again as two halves, the body going
// from progress k−1 to k−½, then on to k; a half that fails is halved again, down to
// 1/2^max_step_cuts of the step (SolverSpec::max_step_cuts). All the attempts' records keep
// step = k and their iterations count on within the step, so the cap holds for each attempt.
#include <functional>
#include <type_traits>
#include <utility>

#include "fabform/model/model.hpp"
#include "fabform/solver/solve.hpp"
#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

/// How a converged load step was solved: how many times a part of it that failed was cut in
/// half, and the smallest part solved, as a fraction of the step (1: the whole step at once).
struct StepCuts {
  int cuts = 0;
  double smallest_fraction = 1.0;
};

/// Told when load step `step` has converged, with its rest state, its own summary (its
/// iterations those of all its attempts) and how it was cut. A callable that takes the first
/// three alone is taken too.
class StepObserver {
 public:
  using Call = std::function<void(int step, const SolverState& state, const Summary& step_summary, const StepCuts& cuts)>;

  StepObserver() = default;
  template <class F, std::enable_if_t<std::is_invocable_v<F&, int, const SolverState&, const Summary&, const StepCuts&>, int> = 0>
  StepObserver(F f) : call_(std::move(f)) {}
  template <class F, std::enable_if_t<std::is_invocable_v<F&, int, const SolverState&, const Summary&> &&
                                          !std::is_invocable_v<F&, int, const SolverState&, const Summary&, const StepCuts&>,
                                      int> = 0>
  StepObserver(F f)
      : call_([f = std::move(f)](int step, const SolverState& state, const Summary& step_summary,
                                 const StepCuts&) mutable { f(step, state, step_summary); }) {}

  explicit operator bool() const { return static_cast<bool>(call_); }
  void operator()(int step, const SolverState& state, const Summary& step_summary, const StepCuts& cuts) const {
    call_(step, state, step_summary, cuts);
  }

 private:
  Call call_;
};

/// Stands every travelling body at its pose after step `step`, the fabric left where it is: where
/// a checkpoint written in that step has them.
void stand_bodies_at_step(Model& model, int step);

/// Moves the bodies to their poses after step `step` − 1 and the fabric with them
/// (step 1: from their placements).
void begin_load_step(Model& model, SolverState& state, int step);

/// The same from progress `from` to progress `to`, in load steps (fractional for a cut step):
/// the bodies go from pose_at(from) to pose_at(to). begin_load_step(model, state, k) is
/// begin_load_step(model, state, k − 1, k), bit for bit.
void begin_load_step(Model& model, SolverState& state, double from, double to);

/// Solves `model` step by step from `state` (std::invalid_argument when no body travels, or
/// when spec.max_step_cuts is not 0 … 20). Returns the run's summary: every step's records in
/// its history (a cut step's every attempt), the total iterations and seconds, and the
/// termination of the last step solved. A step that does not converge is cut (above); the run
/// ends unconverged when a part of 1/2^max_step_cuts of a step fails (its message names the
/// step and says its cuts were exhausted; with max_step_cuts 0, the step's own failure), or at
/// an interrupt or a numerical failure, which are not cut (a NaN is a broken model or state,
/// not a step too long, and a cut would hide it). `resumed` is a checkpoint's summary: the run
/// goes on inside the step its last record belongs to, `state` being that checkpoint's, at the
/// step's whole pose.
///
/// Checkpoints: a run interrupted while a step was being cut goes back to the state the step
/// began from and the bodies to their poses there (the step's records dropped), so that a
/// resume solves the step again from its start and ends bit for bit where the uninterrupted
/// run ends. Limitations: a checkpoint holds no state from before its step began, so a step
/// resumed inside (from its whole pose, as without cuts) is not cut should it fail: the run
/// ends unconverged, its message saying so; and a checkpoint written while a step was being cut
/// (every K iterations or M minutes, the run then killed) holds a state solved for a fractional
/// pose, which cannot be resumed: the run ends unconverged, its message saying so. It is told
/// by the step's records past the cap and by nodes resting inside the body at the whole pose
/// (more than 1000 times on_surface_distance), or by a state that does not re-finish at once;
/// a state that passes these checks goes on as the step's rest.
Summary solve_in_steps(Model& model, SolverState& state, const SolverSpec& spec, const IterationObserver& observer,
                       const StepObserver& step_done, Summary resumed = {});

}  // namespace fabform
