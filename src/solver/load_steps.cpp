#include "fabform/solver/load_steps.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fabform/geometry/nearby_queries.hpp"

namespace fabform {
namespace {

// A part of 1/2^20 of a step is about a millionth of it: further cuts would be a step too long
// for the model rather than for the solver.
constexpr int kMaxStepCuts = 20;

Eigen::Vector3d keep_locked(Eigen::Vector3d point, const Eigen::Vector3d& held, AxisMask locks) {
  for (int axis = 0; axis < 3; ++axis)
    if (locks & (1 << axis)) point[axis] = held[axis];
  return point;
}

// A node resting on a travelling body goes with it, as the tool carries what it presses on;
// friction's anchor goes too, so the node's slip stays what it was on the body.
void carry_resting_nodes(const Model& model, SolverState& state, int body, const Eigen::Isometry3d& move) {
  for (int k = 0; k < model.node_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    NodeContact& contact = state.contact[i];
    if (contact.body != body) continue;
    state.x[i] = keep_locked(move * state.x[i], state.x[i], model.locks[i]);
    contact.anchor = move * contact.anchor;
    contact.normal = move.linear() * contact.normal;
  }
}

// A free node the moved bodies now overlap is put on the surface where it is closest, and
// lands there (its anchor for friction).
void put_overlapped_on_surface(const Model& model, SolverState& state) {
  const AxisMask all = kLockX | kLockY | kLockZ;
  NearbyQueries queries(model.bodies);
  for (int k = 0; k < model.node_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (state.contact[i].active() || model.locks[i] == all) continue;
    for (std::size_t b = 0; b < model.paths.size(); ++b) {
      if (!model.paths[b].moves()) continue;
      if (queries.surely_outside(static_cast<int>(b), state.x[i], 0.0)) continue;
      const SurfacePoint s = queries.closest(static_cast<int>(b), state.x[i]);
      if (s.signed_distance >= 0.0) continue;
      const Eigen::Vector3d on = keep_locked(s.point, state.x[i], model.locks[i]);
      state.x[i] = on;
      state.contact[i] = NodeContact{static_cast<int>(b), s.normal, on};
      break;
    }
  }
}

// The summary a step's solver starts from: the step's own records when the run resumes inside
// it, else none, with the seconds of the steps before so that time runs on.
Summary step_start(const std::vector<IterationRecord>& history, int step, double seconds_before) {
  Summary start;
  start.seconds = seconds_before;
  for (const IterationRecord& r : history)
    if (r.step == step) start.history.push_back(r);
  if (start.history.empty()) return start;
  start.iterations = start.history.back().iteration;
  start.seconds = start.history.back().seconds;
  start.residual_N = start.history.back().residual_N;
  return start;
}

std::string step_message(int step, int steps, const Summary& s) {
  if (s.converged()) return "all " + std::to_string(steps) + " load steps converged; the last: " + s.message;
  return "load step " + std::to_string(step) + " of " + std::to_string(steps) + ": " + s.message;
}

}  // namespace

void begin_load_step(Model& model, SolverState& state, double from, double to) {
  for (std::size_t b = 0; b < model.paths.size(); ++b) {
    const ToolPath& path = model.paths[b];
    if (!path.moves()) continue;
    const Eigen::Isometry3d pose = path.pose_at(to);
    carry_resting_nodes(model, state, static_cast<int>(b), pose * path.pose_at(from).inverse());
    model.bodies[b].move_to(pose);
  }
  put_overlapped_on_surface(model, state);
  state.velocity.clear();  // each step starts from rest
}

void stand_bodies_at_step(Model& model, int step) {
  for (std::size_t b = 0; b < model.paths.size(); ++b)
    if (model.paths[b].moves()) model.bodies[b].move_to(model.paths[b].pose(step));
}

void begin_load_step(Model& model, SolverState& state, int step) {
  begin_load_step(model, state, static_cast<double>(step - 1), static_cast<double>(step));
}

namespace {

// One load step, solved whole or, when that fails, in parts cut in half (load_steps.hpp). Its
// attempts add their records to the run's history (all with step = k) and their figures to the
// run's summary as they end.
class LoadStep {
 public:
  LoadStep(Model& model, SolverState& state, const SolverSpec& spec, const IterationObserver& observer, Summary& run,
           int step, int steps)
      : model_(model), state_(state), spec_(spec), observer_(observer), run_(run), step_(step), steps_(steps),
        cap_(solver_named(spec.name).stop_settings(spec).max_iterations) {}

  // Solves the step; `resumed`: the run goes on inside it from a checkpoint, the bodies and the
  // state already at its whole pose. Returns whether it converged; if not, the run's summary says
  // why.
  bool solve(bool resumed) {
    Bodies bodies_at_start = bodies();
    SolverState at_start;
    if (!resumed) {
      if (spec_.max_step_cuts > 0) at_start = state_;  // a copy only when it may be needed
      begin_load_step(model_, state_, step_);
    }
    // The first attempt is the step as it always was solved: the same start, the same cap.
    Summary start = step_start(run_.history, step_, run_.seconds);
    // Resumed with the step's records past the cap, the step had been cut, and the checkpoint
    // was written at its end (none is written inside a cut: IterationRecord::inside_cut), at its
    // rest, which re-finishes at once: it is given one iteration beyond them, for a position
    // check. One that does not was written as the whole step reached its cap, before the cut.
    const bool cut_before = resumed && spec_.max_step_cuts > 0 && start.iterations >= cap_;
    const Summary whole =
        cut_before ? attempt(capped(start.iterations + 1LL), std::move(start)) : attempt(spec_, std::move(start));
    if (whole.converged()) return true;
    if (whole.termination != Termination::not_converged || spec_.max_step_cuts == 0) return false;
    if (cut_before) return refuse_inside_cut(run_);
    if (resumed) {
      // Limitation: a checkpoint holds no state from before the step began, so there is nothing
      // to cut back to.
      run_.message += "; the run was resumed inside this step from a checkpoint, from which it cannot be cut "
                      "(a cut goes back to the step's start, which a checkpoint does not hold): run the scene "
                      "again without --resume to let the step be cut";
      return false;
    }
    restore(at_start, bodies_at_start);
    ++cuts_.cuts;
    const double from = step_ - 1.0;
    const double half = from + 0.5;
    if (solve_part(from, half, 1) && solve_part(half, step_, 1)) return true;
    if (run_.termination == Termination::numerical_failure)
      run_.message += " (while the step was being cut: in its part from progress " + progress(failed_from_) +
                      " to " + progress(failed_to_) + ")";
    if (run_.termination == Termination::interrupted) {
      // A state inside a cut is at no whole pose, which is all a checkpoint can resume from: the
      // run goes back to where the step began, and --resume solves the step again from there,
      // as the uninterrupted run did.
      restore(at_start, bodies_at_start);
      forget_step();
      run_.message += "; load step " + std::to_string(step_) + " was being cut: its records are dropped and the "
                      "state kept is the one it began from, from which --resume solves it again";
    }
    return false;
  }

  const StepCuts& cuts() const { return cuts_; }
  // The step's own summary: its last attempt's, with every attempt's records and iterations.
  const Summary& summary() const { return last_; }

 private:
  using Bodies = std::vector<Eigen::Isometry3d>;

  // Ends the run that resumed a checkpoint written as the whole step failed, before its cut.
  bool refuse_inside_cut(const Summary& where) {
    run_.termination = Termination::not_converged;
    run_.converged_on = StopCriterion::none;
    run_.residual_N = where.residual_N;
    run_.message = "load step " + std::to_string(step_) + " of " + std::to_string(steps_) +
                   ": the checkpoint was written as the step failed whole, before it was cut, which a checkpoint "
                   "cannot resume: run the scene again without --resume";
    return false;
  }

  // The spec with its cap at `cap` iterations of the step's count.
  SolverSpec capped(long long cap) const {
    SolverSpec spec = spec_;
    spec.set_max_iterations(static_cast<int>(std::min<long long>(cap, std::numeric_limits<int>::max())));
    return spec;
  }

  Bodies bodies() const {
    Bodies poses;
    for (const RigidBody& body : model_.bodies) poses.push_back(body.pose());
    return poses;
  }

  void restore(const SolverState& state, const Bodies& poses) {
    state_ = state;
    for (std::size_t b = 0; b < poses.size(); ++b)
      if (b < model_.paths.size() && model_.paths[b].moves()) model_.bodies[b].move_to(poses[b]);
  }

  // The part of the step from progress `from` to `to`, cut `depth` times, from the state where
  // the last part left it; a part that fails is cut in half while depth < max_step_cuts.
  bool solve_part(double from, double to, int depth) {
    const Bodies bodies_before = bodies();
    const SolverState before = state_;
    begin_load_step(model_, state_, from, to);
    // Its iterations count on within the step, and it has the whole cap of its own.
    Summary start = step_start(run_.history, step_, run_.seconds);
    start.seconds = run_.seconds;
    const int counted = start.iterations;
    const Summary done = attempt(capped(static_cast<long long>(counted) + cap_), std::move(start), true);
    cuts_.smallest_fraction = std::min(cuts_.smallest_fraction, to - from);
    if (done.converged()) return true;
    failed_from_ = from, failed_to_ = to;
    if (done.termination != Termination::not_converged) return false;  // interrupted or broken: not cut
    if (depth >= spec_.max_step_cuts) {
      run_.message = exhausted_message(done, done.iterations - counted >= cap_, from, to);
      return false;
    }
    restore(before, bodies_before);
    ++cuts_.cuts;
    const double middle = from + 0.5 * (to - from);  // exact: the parts are powers of two of a step
    return solve_part(from, middle, depth + 1) && solve_part(middle, to, depth + 1);
  }

  // Solves from `start` with `spec`, the records numbered within the step.
  Summary attempt(const SolverSpec& spec, Summary start, bool inside_cut = false) {
    run_.history.erase(std::remove_if(run_.history.begin(), run_.history.end(),
                                      [&](const IterationRecord& r) { return r.step == step_; }),
                       run_.history.end());
    const Summary done = fabform::solve(model_, state_, spec, [&](IterationRecord r) {
      r.step = step_;
      r.inside_cut = inside_cut;
      if (observer_) observer_(r);
    }, std::move(start));
    for (IterationRecord r : done.history) r.step = step_, run_.history.push_back(r);
    run_.iterations = total_iterations(run_.history);
    run_.residual_N = done.residual_N;
    run_.worst_node = done.worst_node;
    run_.seconds = done.seconds;
    run_.termination = done.termination;
    run_.converged_on = done.converged_on;
    run_.position_error_m = done.position_error_m;
    run_.linear_solver = done.linear_solver;
    run_.linear_iterations += done.linear_iterations;
    run_.message = step_message(step_, steps_, done);
    const long linear_iterations = last_.linear_iterations + done.linear_iterations;
    last_ = done;
    last_.linear_iterations = linear_iterations;
    return done;
  }

  // The run goes back to the end of the step before: the step's records are dropped.
  void forget_step() {
    run_.history.erase(std::remove_if(run_.history.begin(), run_.history.end(),
                                      [&](const IterationRecord& r) { return r.step == step_; }),
                       run_.history.end());
    run_.iterations = total_iterations(run_.history);
    if (!run_.history.empty()) run_.residual_N = run_.history.back().residual_N;
    run_.worst_node = -1;
  }

  static std::string progress(double at) {
    std::ostringstream text;
    text.precision(10);
    text << at;
    return text.str();
  }

  // Why the smallest part failed: its own cap reached (its iterations count on within the
  // step, so the solver's message would give the count, not the cap), or its line search stalled.
  std::string exhausted_message(const Summary& done, bool capped, double from, double to) const {
    std::ostringstream text;
    text << "load step " << step_ << " of " << steps_ << ": its cuts were exhausted (max_step_cuts = "
         << spec_.max_step_cuts << "): the part of 1/" << (1LL << spec_.max_step_cuts) << " of the step from progress "
         << progress(from) << " to " << progress(to) << " did not converge either: ";
    text.precision(3);
    if (capped)
      text << "iteration cap " << cap_ << " reached with ||V||inf = " << done.residual_N << " N > e = "
           << done.tolerance_N << " N (worst node " << done.worst_node << ")";
    else
      text << done.message;
    return text.str();
  }

  Model& model_;
  SolverState& state_;
  const SolverSpec& spec_;
  const IterationObserver& observer_;
  Summary& run_;
  const int step_;
  const int steps_;
  const int cap_;
  StepCuts cuts_;
  Summary last_;
  double failed_from_ = 0.0;  // the part that failed last
  double failed_to_ = 0.0;
};

}  // namespace

Summary solve_in_steps(Model& model, SolverState& state, const SolverSpec& spec, const IterationObserver& observer,
                       const StepObserver& step_done, Summary resumed) {
  const int steps = model.load_steps();
  if (steps == 0) throw std::invalid_argument("solve_in_steps: no body travels");
  if (spec.max_step_cuts < 0 || spec.max_step_cuts > kMaxStepCuts)
    throw std::invalid_argument("solve_in_steps: max_step_cuts must be 0 ... " + std::to_string(kMaxStepCuts));
  Summary run = begin_summary(spec.name, spec.tolerance_N(), std::move(resumed), spec.tolerance_m());
  const int resumed_step = run.history.empty() ? 0 : run.history.back().step;
  // The bodies stand where the checkpoint's step put them; the state is already carried.
  if (resumed_step > 0) stand_bodies_at_step(model, resumed_step);
  for (int step = resumed_step > 0 ? resumed_step : 1; step <= steps; ++step) {
    LoadStep load_step(model, state, spec, observer, run, step, steps);
    if (!load_step.solve(step == resumed_step)) return run;
    if (step_done) step_done(step, state, load_step.summary(), load_step.cuts());
  }
  return run;
}

}  // namespace fabform
