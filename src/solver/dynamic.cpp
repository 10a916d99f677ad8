#include "fabform/solver/dynamic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "fabform/angles.hpp"
#include "fabform/model/equilibrium.hpp"
#include "fabform/solver/contact_move.hpp"
#include "fabform/solver/solver_loop.hpp"
#include "fabform/solver/solver_registry.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {

std::string DynamicOptions::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (std::string why = stop_settings(*this).invalid_reason(field); !why.empty()) return why;
  if (!(std::isfinite(areal_density_kg_m2) && areal_density_kg_m2 > 0.0))
    return bad("areal_density_kg_m2", "must be a positive, finite density");
  if (damping && !(*damping >= 0.0 && *damping < 1.0)) return bad("damping", "must be in [0, 1)");
  if (!(time_step_fraction > 0.0 && time_step_fraction <= 1.0))
    return bad("time_step_fraction", "must be in (0, 1]");
  if (!(stretch_limit >= 0.0 && stretch_limit <= 100.0)) return bad("stretch_limit", "must be in [0, 100]");
  return "";
}

double inertia_density(const Model& model, const DynamicOptions& options) {
  return model.areal_density_kg_m2 > 0.0 ? model.areal_density_kg_m2 : options.areal_density_kg_m2;
}

std::vector<double> node_masses(const Model& model, double areal_density_kg_m2) {
  std::vector<double> mass = model.fabric.node_areas();
  for (double& m : mass) m *= areal_density_kg_m2;
  return mass;
}

namespace {


}  // namespace

TimeStep stable_time_step(const Model& model, const std::vector<double>& masses, double fraction) {
  StiffnessBound bound{std::vector<double>(masses.size(), 0.0), 0.0};
  for (const auto& term : model.terms) term->bound_stiffness(model, bound);
  const std::vector<double>& stiffness = bound.per_node;
  const double stiffest = bound.stiffest_element;
  TimeStep step;
  step.stability_limit = step.seed_limit = std::numeric_limits<double>::infinity();
  double lightest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < masses.size(); ++i) {
    if (model.locks[i] == (kLockX | kLockY | kLockZ)) continue;  // a held node does not oscillate
    lightest = std::min(lightest, masses[i]);
    if (stiffness[i] > 0.0) step.stability_limit = std::min(step.stability_limit, std::sqrt(2.0 * masses[i] / stiffness[i]));
  }
  if (stiffest > 0.0 && std::isfinite(lightest)) step.seed_limit = kPi * std::sqrt(lightest / stiffest);
  step.seconds = fraction * std::min(step.stability_limit, step.seed_limit);
  return step;
}

namespace {

class Dynamics {
 public:
  Dynamics(const Model& model, SolverState& state, const DynamicOptions& options)
      : model_(model),
        state_(state),
        options_(options),
        mass_(node_masses(model, inertia_density(model, options))),
        step_(stable_time_step(model, mass_, options.time_step_fraction)),
        damping_(options.damping ? *options.damping : default_damping(model)) {
    if (state.velocity.size() != state.x.size())
      state.velocity.assign(state.x.size(), Eigen::Vector3d::Zero());
    if (options.stretch_limit > 0.0) order_springs();
  }

  const TimeStep& time_step() const { return step_; }
  double damping() const { return damping_; }

  std::vector<Eigen::Vector3d> forces() const { return node_forces(model_, state_.x); }

  /// One time step driven by the resultants R at the current positions.
  void advance(const std::vector<Eigen::Vector3d>& forces) {
    start_drags();
// Dynamic: a node on a body costs more than a free one.
#pragma omp parallel for schedule(dynamic, 256) if (model_.node_count() >= kMinParallelItems)
    for (int k = 0; k < model_.node_count(); ++k) advance_node(k, forces[static_cast<std::size_t>(k)]);
    if (options_.stretch_limit > 0.0) limit_stretch();
  }

 private:
  static double default_damping(const Model& model) {
    const int divisions = model.fabric.divisions_across();
    return std::min(0.5, 4.0 / std::max(divisions, 1));
  }

  void advance_node(int k, const Eigen::Vector3d& r) {
    const auto i = static_cast<std::size_t>(k);
    const AxisMask lock = model_.locks[i];
    if (lock == (kLockX | kLockY | kLockZ)) return;
    NodeContact& contact = state_.contact[i];
    if (contact.active() && remove_locked(r, lock).dot(contact.normal) > 0.0)
      contact = NodeContact{};  // R points out of the body: the node leaves it (§3.2.2)
    Eigen::Vector3d& v = state_.velocity[i];
    // Within the node's free directions: on a body, within its tangent plane, whichever way
    // the normal part pointed (move_node expects a tangent step on a body).
    const NodeFreedom freedom{lock, contact.active() ? &contact.normal : nullptr};
    v = freedom.project((1.0 - damping_) * v + step_.seconds / mass_[i] * r);
    for (const auto& drag : drags_) v = drag->after(k, step_.seconds, mass_[i], v, freedom);
    if (const double mu = contact_friction(model_, contact); mu > 0.0) v = coulomb(v, r, mu, lock, contact.normal, mass_[i]);
    const NodeMove moved = move_node(model_, k, state_.x[i], step_.seconds * v, contact);
    if (moved.contact.active()) v -= std::min(v.dot(moved.contact.normal), 0.0) * moved.contact.normal;
    state_.x[i] = moved.x;
    contact = moved.contact;
  }

  // Coulomb friction over one step, taken as an impulse (a return mapping): the body can take
  // up to μ·λ·Δt of the node's tangential momentum, λ the force pressing it on the body. If
  // that stops it, it sticks; else it slides on, slowed by that much.
  Eigen::Vector3d coulomb(const Eigen::Vector3d& v, const Eigen::Vector3d& r, double mu, AxisMask lock,
                          const Eigen::Vector3d& normal, double mass) const {
    const double held = mu * pressing_force(r, lock, normal) * step_.seconds / mass;  // the speed friction can take away
    const double speed = v.norm();
    return speed <= held ? Eigen::Vector3d::Zero() : Eigen::Vector3d((1.0 - held / speed) * v);
  }

  // The velocity-dependent terms, taken at the step's start, before any node moves.
  void start_drags() {
    drags_.clear();
    for (const auto& term : model_.terms)
      if (auto drag = term->drag(model_, state_.x)) drags_.push_back(std::move(drag));
  }

  // Provot's deformation constraint, one pass: a spring longer than (1 + τ)·L is shortened to
  // it. As seed 000 does from its pin, the pass works outward from the held nodes, and the end
  // farther from them moves toward the nearer one; ends equally far both move half way. A node
  // held on any axis does not move, so a held coordinate never changes.
  void limit_stretch() {
    const double ratio = 1.0 + options_.stretch_limit;
    for (const int index : stretch_order_) {
      const Spring& s = model_.fabric.springs()[static_cast<std::size_t>(index)];
      const auto a = static_cast<std::size_t>(s.a), b = static_cast<std::size_t>(s.b);
      const Eigen::Vector3d d = state_.x[b] - state_.x[a];
      const double excess = d.norm() - ratio * s.rest_length;
      if (!(excess > 0.0)) continue;
      const bool a_moves = model_.locks[a] == 0 && hops_[a] >= hops_[b];
      const bool b_moves = model_.locks[b] == 0 && hops_[b] >= hops_[a];
      if (!a_moves && !b_moves) continue;
      const Eigen::Vector3d pull = (a_moves && b_moves ? 0.5 : 1.0) * excess * d.normalized();
      if (a_moves) shift(s.a, pull);
      if (b_moves) shift(s.b, -pull);
    }
  }

  // Springs by their distance in springs from the nearest held node (nearest first).
  void order_springs() {
    const int n = model_.node_count();
    hops_.assign(static_cast<std::size_t>(n), n);  // n: no held node reachable
    std::vector<int> queue;
    for (int k = 0; k < n; ++k)
      if (model_.locks[static_cast<std::size_t>(k)] != 0) hops_[static_cast<std::size_t>(k)] = 0, queue.push_back(k);
    for (std::size_t head = 0; head < queue.size(); ++head)
      for (const int spring : model_.fabric.springs_at(queue[head])) {
        const Spring& s = model_.fabric.springs()[static_cast<std::size_t>(spring)];
        const int other = s.a == queue[head] ? s.b : s.a;
        int& hops = hops_[static_cast<std::size_t>(other)];
        if (hops > hops_[static_cast<std::size_t>(queue[head])] + 1)
          hops = hops_[static_cast<std::size_t>(queue[head])] + 1, queue.push_back(other);
      }
    const auto level = [&](int index) {
      const Spring& s = model_.fabric.springs()[static_cast<std::size_t>(index)];
      return std::min(hops_[static_cast<std::size_t>(s.a)], hops_[static_cast<std::size_t>(s.b)]);
    };
    stretch_order_.resize(model_.fabric.springs().size());
    for (std::size_t i = 0; i < stretch_order_.size(); ++i) stretch_order_[i] = static_cast<int>(i);
    std::stable_sort(stretch_order_.begin(), stretch_order_.end(),
                     [&](int p, int q) { return level(p) < level(q); });
  }

  void shift(int k, const Eigen::Vector3d& by) {
    const auto i = static_cast<std::size_t>(k);
    NodeContact& contact = state_.contact[i];
    const Eigen::Vector3d step = contact.active() ? by - by.dot(contact.normal) * contact.normal : by;
    const NodeMove moved = move_node(model_, k, state_.x[i], step, contact);
    state_.x[i] = moved.x;
    contact = moved.contact;
  }

  const Model& model_;
  SolverState& state_;
  const DynamicOptions& options_;
  std::vector<double> mass_;
  TimeStep step_;
  double damping_;
  std::vector<std::unique_ptr<StepDrag>> drags_;  // the current step's
  std::vector<int> hops_;           // springs from each node to the nearest held node
  std::vector<int> stretch_order_;  // spring indices, nearest the held nodes first
};

std::string step_note(const Dynamics& dynamics) {
  std::ostringstream text;
  text.precision(3);
  text << "; time step " << dynamics.time_step().seconds << " s (stability limit "
       << dynamics.time_step().stability_limit << " s, seed 004's pi*sqrt(m/k) "
       << dynamics.time_step().seed_limit << " s), damping f = " << dynamics.damping() << " per step";
  return text.str();
}

}  // namespace

Summary dynamic(const Model& model, SolverState& state, const DynamicOptions& options,
                const IterationObserver& observer, Summary resumed) {
  if (const std::string why = options.invalid_reason(); !why.empty())
    throw std::invalid_argument("dynamic: " + why);
  if (const std::string why = solver_refusal(model, "dynamic"); !why.empty())
    throw std::invalid_argument("dynamic: " + why);
  const auto started = std::chrono::steady_clock::now();
  Dynamics dynamics(model, state, options);
  // The forces at the state the last step reached give its residual and drive the next step.
  std::vector<Eigen::Vector3d> forces;
  const SolverSteps steps = rate_estimated_steps(state, options.tolerance_m, [&] { dynamics.advance(forces); }, [&] {
    forces = dynamics.forces();
    return measure_state(model, state, forces);
  });
  Summary summary = run_solver_loop("dynamic", stop_settings(options), steps, observer, std::move(resumed), started);
  summary.message += step_note(dynamics);
  return summary;
}

}  // namespace fabform
