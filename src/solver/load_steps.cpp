#include "fabform/solver/load_steps.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "fabform/geometry/nearby_queries.hpp"

namespace fabform {
namespace {

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

void begin_load_step(Model& model, SolverState& state, int step) {
  for (std::size_t b = 0; b < model.paths.size(); ++b) {
    const ToolPath& path = model.paths[b];
    if (!path.moves()) continue;
    const Eigen::Isometry3d to = path.pose(step);
    carry_resting_nodes(model, state, static_cast<int>(b), to * path.pose(step - 1).inverse());
    model.bodies[b].move_to(to);
  }
  put_overlapped_on_surface(model, state);
  state.velocity.clear();  // each step starts from rest
}

Summary solve_in_steps(Model& model, SolverState& state, const SolverSpec& spec, const IterationObserver& observer,
                       const StepObserver& step_done, Summary resumed) {
  const int steps = model.load_steps();
  if (steps == 0) throw std::invalid_argument("solve_in_steps: no body travels");
  Summary run = begin_summary(spec.name, spec.tolerance_N(), std::move(resumed), spec.tolerance_m());
  const int resumed_step = run.history.empty() ? 0 : run.history.back().step;
  // The bodies stand where the checkpoint's step put them; the state is already carried.
  for (std::size_t b = 0; b < model.paths.size() && resumed_step > 0; ++b)
    if (model.paths[b].moves()) model.bodies[b].move_to(model.paths[b].pose(resumed_step));
  for (int step = resumed_step > 0 ? resumed_step : 1; step <= steps; ++step) {
    if (step != resumed_step) begin_load_step(model, state, step);
    const Summary start = step_start(run.history, step, run.seconds);
    run.history.erase(std::remove_if(run.history.begin(), run.history.end(),
                                     [&](const IterationRecord& r) { return r.step == step; }),
                      run.history.end());
    const Summary done = solve(model, state, spec, [&](IterationRecord r) {
      r.step = step;
      if (observer) observer(r);
    }, start);
    for (IterationRecord r : done.history) r.step = step, run.history.push_back(r);
    run.iterations = total_iterations(run.history);
    run.residual_N = done.residual_N;
    run.worst_node = done.worst_node;
    run.seconds = done.seconds;
    run.termination = done.termination;
    run.converged_on = done.converged_on;
    run.position_error_m = done.position_error_m;
    run.linear_solver = done.linear_solver;
    run.linear_iterations += done.linear_iterations;
    run.message = step_message(step, steps, done);
    if (!done.converged()) return run;
    if (step_done) step_done(step, state, done);
  }
  return run;
}

}  // namespace fabform
