#include "fabform/solver/dynamic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/stretch_forces.hpp"
#include "fabform/model/wind.hpp"
#include "fabform/solver/contact_move.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {

std::string DynamicOptions::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (!(std::isfinite(tolerance_N) && tolerance_N > 0.0))
    return bad("tolerance_N", "must be a positive, finite force");
  if (max_iterations < 0) return bad("max_iterations", "must not be negative");
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

constexpr double kPi = 3.14159265358979323846;

// The steepest segment of a table (N/m per unit strain); the slack range of a tension-only
// table has slope 0, and the extended end segments keep their slopes.
double steepest_slope(const TensionTable& table) {
  double steepest = 0.0;
  const auto& p = table.points();
  for (std::size_t i = 1; i < p.size(); ++i)
    steepest = std::max(steepest, (p[i].tension_N_per_m - p[i - 1].tension_N_per_m) /
                                      (p[i].strain - p[i - 1].strain));
  return steepest;
}

double spring_stiffness_bound(const Model& model, const Spring& s) {
  return s.width * steepest_slope(model.table(s.kind)) / s.rest_length;
}

// A hinge's stiffness 2·B·s·c·cᵀ (per axis): half of each node's row sum, which is what a
// spring's k is to the bound below (its block's row sums are 2k).
void add_hinge_stiffness(const Model& model, std::vector<double>* stiffness) {
  if (!model.bending_rigidity_Nm) return;
  for (const Hinge& h : model.fabric.hinges()) {
    const HingeStencil stencil = hinge_stencil(h);
    double sum = 0.0;
    for (int k = 0; k < stencil.count; ++k) sum += std::abs(stencil.weight[static_cast<std::size_t>(k)]);
    for (int k = 0; k < stencil.count; ++k)
      (*stiffness)[static_cast<std::size_t>(stencil.node[static_cast<std::size_t>(k)])] +=
          *model.bending_rigidity_Nm * h.shape_factor * std::abs(stencil.weight[static_cast<std::size_t>(k)]) * sum;
  }
}

}  // namespace

TimeStep stable_time_step(const Model& model, const std::vector<double>& masses, double fraction) {
  std::vector<double> stiffness(masses.size(), 0.0);
  double stiffest = 0.0;
  for (const Spring& s : model.fabric.springs()) {
    const double k = spring_stiffness_bound(model, s);
    stiffness[static_cast<std::size_t>(s.a)] += k;
    stiffness[static_cast<std::size_t>(s.b)] += k;
    stiffest = std::max(stiffest, k);
  }
  add_hinge_stiffness(model, &stiffness);
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

// A velocity along the node's free axes, and for a node on a body within its tangent plane,
// whichever way the normal part pointed (move_node expects a tangent step on a body).
Eigen::Vector3d sliding(const Eigen::Vector3d& v, AxisMask lock, const NodeContact& contact) {
  const Eigen::Vector3d free = remove_locked(v, lock);
  if (!contact.active()) return free;
  const Eigen::Vector3d normal = remove_locked(contact.normal, lock);
  const double length2 = normal.squaredNorm();
  return length2 == 0.0 ? free : free - (free.dot(normal) / length2) * normal;
}

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

  std::vector<Eigen::Vector3d> forces() const {
    std::vector<Eigen::Vector3d> r(state_.x.size());
#pragma omp parallel for schedule(static) if (model_.node_count() >= kMinParallelItems)
    for (int k = 0; k < model_.node_count(); ++k) r[static_cast<std::size_t>(k)] = node_force(model_, state_.x, k);
    return r;
  }

  /// One time step driven by the resultants R at the current positions.
  void advance(const std::vector<Eigen::Vector3d>& forces) {
    if (model_.wind) find_normals();
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
    v = sliding((1.0 - damping_) * v + step_.seconds / mass_[i] * r, lock, contact);
    // The drag acts within the directions the node may move in: its normal projected on them,
    // so that no reaction on a held axis leaks into a free one through (n·v)·n.
    if (model_.wind)
      v = after_wind_drag(step_.seconds * model_.wind->coefficient_N_s_m3 * model_.fabric.node_areas()[i] / mass_[i],
                          sliding(normals_[i], lock, contact), v);
    const NodeMove moved = move_node(model_, k, state_.x[i], step_.seconds * v, contact);
    if (moved.contact.active()) v -= std::min(v.dot(moved.contact.normal), 0.0) * moved.contact.normal;
    state_.x[i] = moved.x;
    contact = moved.contact;
  }

  // Every node's normal before any moves: advance_node's drag needs them at the step's start.
  void find_normals() {
    normals_.resize(state_.x.size());
#pragma omp parallel for schedule(static) if (model_.node_count() >= kMinParallelItems)
    for (int k = 0; k < model_.node_count(); ++k)
      normals_[static_cast<std::size_t>(k)] = node_normal(model_.fabric, state_.x, k);
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
  std::vector<Eigen::Vector3d> normals_;  // at the step's start, when the wind blows
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
  if (model.wind)
    if (const std::string why = model.wind->invalid_reason(); !why.empty()) throw std::invalid_argument("dynamic: " + why);
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  Dynamics dynamics(model, state, options);
  Summary summary = begin_summary("dynamic", options.tolerance_N, std::move(resumed));
  const double earlier_seconds = summary.seconds;
  for (int iteration = summary.iterations;; ++iteration) {
    // The forces at the state the last step reached give its residual and drive the next step.
    const std::vector<Eigen::Vector3d> forces = dynamics.forces();
    const StateResidual m = measure_state(model, state, forces);
    const double seconds =
        earlier_seconds + std::chrono::duration<double>(Clock::now() - started).count();
    const IterationRecord record{iteration, m.max_residual_N, seconds, m.contact_nodes};
    if (record_iteration(summary, record, m.worst_node, options.max_iterations, observer)) break;
    dynamics.advance(forces);
  }
  summary.message = stop_message(summary) + step_note(dynamics);
  return summary;
}

}  // namespace fabform
