#include "fabform/solver/relax.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/stretch_forces.hpp"

namespace fabform {

std::string RelaxOptions::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (!(C > 1.0 && C <= 1e6)) return bad("C", "must be greater than 1 and at most 1e6");
  if (!(std::isfinite(tolerance_N) && tolerance_N > 0.0))
    return bad("tolerance_N", "must be a positive, finite force");
  if (max_iterations < 0) return bad("max_iterations", "must not be negative");
  if (!(min_step_fraction >= 1e-300 && min_step_fraction < 1.0))
    return bad("min_step_fraction", "must be in [1e-300, 1)");
  // Bounds the divisions per node and sweep (C barely above 1 would take billions).
  if (std::log(1.0 / min_step_fraction) / std::log(C) > 1e5)
    return bad("C", "is too close to 1: over 100000 step divisions per node and sweep");
  return "";
}

SolverState SolverState::at_start(const Model& model) {
  return {model.start, std::vector<NodeContact>(model.start.size())};
}

namespace {

struct Candidate {
  Eigen::Vector3d x;
  NodeContact contact;
};

class Relaxation {
 public:
  Relaxation(const Model& model, SolverState& state, const RelaxOptions& options)
      : model_(model),
        state_(state),
        options_(options),
        step_attempts_(static_cast<int>(
            std::ceil(std::log(1.0 / options.min_step_fraction) / std::log(options.C)))) {}

  void sweep() {
    for (int k = 0; k < model_.node_count(); ++k) relax_node(k);
  }

  double node_residual(int k, const Eigen::Vector3d& x, const NodeContact& contact) const {
    const Eigen::Vector3d r = node_force_at(model_, state_.x, k, x);
    return unbalanced_force(r, lock(k), contact.active() ? &contact.normal : nullptr).norm();
  }

  struct Measure {
    double max_residual = 0.0;
    int worst_node = -1;
    int contact_nodes = 0;
  };
  Measure measure() const {
    Measure m;
    for (int k = 0; k < model_.node_count(); ++k) {
      const auto& c = state_.contact[static_cast<std::size_t>(k)];
      const double v = node_residual(k, state_.x[static_cast<std::size_t>(k)], c);
      m.contact_nodes += c.active() ? 1 : 0;
      if (std::isnan(v)) return {v, k, m.contact_nodes};  // a broken node decides the run
      if (v > m.max_residual || m.worst_node < 0) m.max_residual = v, m.worst_node = k;
    }
    return m;
  }

 private:
  AxisMask lock(int k) const { return model_.locks[static_cast<std::size_t>(k)]; }

  void relax_node(int k) {
    const auto i = static_cast<std::size_t>(k);
    if (lock(k) == (kLockX | kLockY | kLockZ)) return;
    NodeContact& contact = state_.contact[i];
    const Eigen::Vector3d r = node_force(model_, state_.x, k);
    if (contact.active() && remove_locked(r, lock(k)).dot(contact.normal) > 0.0)
      contact = NodeContact{};  // R points out of the body: the node leaves it (§3.2.2)
    const Eigen::Vector3d push =
        unbalanced_force(r, lock(k), contact.active() ? &contact.normal : nullptr);
    const double residual = push.norm();
    if (!(residual > 0.0)) return;
    const Eigen::Vector3d direction = push / residual;
    double step = first_step_length(k);
    for (int attempt = 0; attempt < step_attempts_; ++attempt, step /= options_.C) {
      const Candidate candidate = move(k, direction * step, contact);
      if (node_residual(k, candidate.x, candidate.contact) < residual) {
        state_.x[i] = candidate.x;
        contact = candidate.contact;
        return;
      }
    }
  }

  // ξ = Σ|d_k| / C (Eq. 4). With every spring at rest length ξ would be 0 although a
  // constraint may still leave a force; the mean rest length / C is used then.
  double first_step_length(int k) const {
    const double deformation = deformation_sum(model_, state_.x, k);
    if (deformation > 0.0) return deformation / options_.C;
    double rest = 0.0;
    int count = 0;
    for (const int s : model_.grid.springs_at(k))
      if (s >= 0) rest += model_.grid.springs()[static_cast<std::size_t>(s)].rest_length, ++count;
    return rest / std::max(count, 1) / options_.C;
  }

  Candidate move(int k, const Eigen::Vector3d& step, const NodeContact& contact) const {
    const Eigen::Vector3d& from = state_.x[static_cast<std::size_t>(k)];
    const Eigen::Vector3d to = from + remove_locked(step, lock(k));
    if (!contact.active()) return fly(from, to, lock(k));
    if (lock(k) == 0) return slide(to, (to - from).norm(), contact.body);
    return slide_locked(from, to, contact, lock(k));
  }

  // A contact node moved on the tangent plane is projected back onto the surface (Fig. 8).
  // The node was on the surface, so the surface is within the step's length of `to`.
  Candidate slide(const Eigen::Vector3d& to, double step_length, int body) const {
    const RigidBody& surface = model_.bodies[static_cast<std::size_t>(body)];
    const auto s = surface.closest_within(to, 2.0 * step_length + 1e-6 * surface.box().diagonal());
    const SurfacePoint projected = s ? *s : surface.closest(to);
    return {projected.point, NodeContact{body, projected.normal}};
  }

  // A node held on some axes cannot be projected to the closest surface point: that would move
  // it along them. It returns to the surface along the free part of the normal instead, or, if
  // the surface fell away further than the step, it is free.
  Candidate slide_locked(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                         const NodeContact& contact, AxisMask locks) const {
    const Eigen::Vector3d along = remove_locked(contact.normal, locks).normalized();
    const double reach = 2.0 * (to - from).norm();
    const RigidBody& body = model_.bodies[static_cast<std::size_t>(contact.body)];
    const auto s = body.first_entry(to + reach * along, to - reach * along);
    if (!s) return {to, NodeContact{}};
    return {keep_locked(s->point, to, locks), NodeContact{contact.body, s->normal}};
  }

  // Entry points are snapped onto their triangle, which can move them by a rounding error;
  // a held coordinate must not move at all.
  static Eigen::Vector3d keep_locked(Eigen::Vector3d point, const Eigen::Vector3d& reference,
                                     AxisMask locks) {
    for (int axis = 0; axis < 3; ++axis)
      if (locks & (1 << axis)) point[axis] = reference[axis];
    return point;
  }

  // A free node moves straight; if the move enters a body, it stops on the surface there.
  Candidate fly(const Eigen::Vector3d& from, const Eigen::Vector3d& to, AxisMask locks) const {
    Candidate result{to, NodeContact{}};
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
      const auto entry = entry_point(model_.bodies[b], from, to, locks);
      if (entry && (entry->point - from).norm() < nearest) {
        nearest = (entry->point - from).norm();
        result = {keep_locked(entry->point, to, locks), NodeContact{static_cast<int>(b), entry->normal}};
      }
    }
    return result;
  }

  // Embree's single-precision rays can slip through a shared edge (by ~1e-7 of the body's
  // size); a move that ends just inside the body, no deeper than the move is long plus such a
  // slip, entered it too and stops on the surface (unless that would move a locked axis).
  static std::optional<SurfacePoint> entry_point(const RigidBody& body, const Eigen::Vector3d& from,
                                                 const Eigen::Vector3d& to, AxisMask locks) {
    if (auto entry = body.first_entry(from, to)) return entry;
    if (locks != 0) return std::nullopt;
    const double reach = (to - from).norm() + 1e-6 * body.box().diagonal();
    const auto s = body.closest_within(to, reach);
    if (s && s->signed_distance < 0.0) return s;
    return std::nullopt;
  }

  const Model& model_;
  SolverState& state_;
  const RelaxOptions& options_;
  int step_attempts_;  // divisions by C until ξ is min_step_fraction of its first value
};

std::string stop_message(const Summary& s) {
  std::ostringstream text;
  text.precision(3);
  if (s.termination == Termination::converged)
    text << "||V||inf = " << s.residual_N << " N <= e = " << s.tolerance_N << " N after "
         << s.iterations << " iterations";
  else if (s.termination == Termination::numerical_failure)
    text << "non-finite residual at node " << s.worst_node << " in iteration " << s.iterations;
  else
    text << "iteration cap " << s.iterations << " reached with ||V||inf = " << s.residual_N
         << " N > e = " << s.tolerance_N << " N (worst node " << s.worst_node << ")";
  return text.str();
}

}  // namespace

Summary relax(const Model& model, SolverState& state, const RelaxOptions& options,
              const IterationObserver& observer) {
  if (const std::string why = options.invalid_reason(); !why.empty())
    throw std::invalid_argument("relax: " + why);
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  Relaxation relaxation(model, state, options);
  Summary summary;
  summary.solver = "relax";
  summary.tolerance_N = options.tolerance_N;
  for (int iteration = 0;; ++iteration) {
    if (iteration > 0) relaxation.sweep();
    const auto m = relaxation.measure();
    const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
    const IterationRecord record{iteration, m.max_residual, seconds, m.contact_nodes};
    summary.history.push_back(record);
    if (observer) observer(record);
    summary.iterations = iteration;
    summary.residual_N = m.max_residual;
    summary.worst_node = m.worst_node;
    summary.seconds = seconds;
    if (!std::isfinite(m.max_residual)) {
      summary.termination = Termination::numerical_failure;
      break;
    }
    if (m.max_residual <= options.tolerance_N) {
      summary.termination = Termination::converged;
      break;
    }
    if (iteration >= options.max_iterations) {
      summary.termination = Termination::not_converged;
      break;
    }
  }
  summary.message = stop_message(summary);
  return summary;
}

}  // namespace fabform
