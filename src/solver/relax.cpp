#include "fabform/solver/relax.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/potential_energy.hpp"
#include "fabform/model/spring_strains.hpp"
#include "fabform/solver/contact_move.hpp"
#include "fabform/solver/solver_loop.hpp"
#include "fabform/solver/solver_registry.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {

std::string RelaxOptions::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (!(C > 1.0 && C <= 1e6)) return bad("C", "must be greater than 1 and at most 1e6");
  if (std::string why = stop_settings(*this).invalid_reason(field); !why.empty()) return why;
  if (!(min_step_fraction >= 1e-300 && min_step_fraction < 1.0))
    return bad("min_step_fraction", "must be in [1e-300, 1)");
  // Bounds the divisions per node and sweep (C barely above 1 would take billions).
  if (std::log(1.0 / min_step_fraction) / std::log(C) > 1e5)
    return bad("C", "is too close to 1: over 100000 step divisions per node and sweep");
  return "";
}

namespace {

class Relaxation {
 public:
  Relaxation(const Model& model, SolverState& state, const RelaxOptions& options)
      : model_(model),
        state_(state),
        options_(options),
        step_attempts_(static_cast<int>(
            std::ceil(std::log(1.0 / options.min_step_fraction) / std::log(options.C)))) {}

  // Colour by colour (the checkerboard for a rectangle's warp and weft springs): a node's springs
  // and hinges reach only nodes of other colours, so the nodes of one colour relax independently of each other, in
  // parallel, with the same result for any thread count.
  void sweep() {
    for (const std::vector<int>& nodes : model_.fabric.colours()) {
      const auto count = static_cast<std::ptrdiff_t>(nodes.size());
#pragma omp parallel for schedule(dynamic, 256) if (count >= kMinParallelItems / 2)
      for (std::ptrdiff_t k = 0; k < count; ++k) relax_node(nodes[static_cast<std::size_t>(k)]);
    }
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
    if (take_step(k, direction, [&](const NodeMove& candidate) {
          return node_residual(model_, state_, k, candidate.x, candidate.contact) < residual;
        }))
      return;
    // Seed 003's rule alone can hold a node for ever once its tension-only springs go slack
    // under a load: wherever it moves within the slack, the force on it is its load, unchanged,
    // and a step out of the slack overshoots. Then the first step that lowers the node's
    // energy is taken. Without loads, seed 003's rule is kept as published.
    if (!model_.loaded()) return;
    take_step(k, direction, [&](const NodeMove& candidate) {
      return node_energy_change(model_, state_.x, k, candidate.x) < 0.0;
    });
  }

  // Steps of ξ, ξ/C, ξ/C², … along `direction` until `accept` takes one; false when none is.
  template <class Accept>
  bool take_step(int k, const Eigen::Vector3d& direction, Accept accept) {
    const auto i = static_cast<std::size_t>(k);
    NodeContact& contact = state_.contact[i];
    double step = first_step_length(k);
    for (int attempt = 0; attempt < step_attempts_; ++attempt, step /= options_.C) {
      const NodeMove candidate = move_node(model_, k, state_.x[i], direction * step, contact);
      if (accept(candidate)) {
        state_.x[i] = candidate.x;
        contact = candidate.contact;
        return true;
      }
    }
    return false;
  }

  // ξ = Σ|d_k| / C (Eq. 4). With every spring at rest length ξ would be 0 although a
  // constraint may still leave a force; the mean rest length / C is used then.
  double first_step_length(int k) const {
    const double deformation = deformation_sum(model_, state_.x, k);
    if (deformation > 0.0) return deformation / options_.C;
    double rest = 0.0;
    int count = 0;
    for (const int s : model_.fabric.springs_at(k))
      rest += model_.fabric.springs()[static_cast<std::size_t>(s)].rest_length, ++count;
    return rest / std::max(count, 1) / options_.C;
  }

  const Model& model_;
  SolverState& state_;
  const RelaxOptions& options_;
  int step_attempts_;  // divisions by C until ξ is min_step_fraction of its first value
};

}  // namespace

Summary relax(const Model& model, SolverState& state, const RelaxOptions& options,
              const IterationObserver& observer, Summary resumed) {
  if (const std::string why = options.invalid_reason(); !why.empty())
    throw std::invalid_argument("relax: " + why);
  if (const std::string why = solver_refusal(model, "relax"); !why.empty())
    throw std::invalid_argument("relax: " + why);
  const auto started = std::chrono::steady_clock::now();
  Relaxation relaxation(model, state, options);
  const SolverSteps steps = rate_estimated_steps(state, options.tolerance_m, [&] { relaxation.sweep(); },
                                                 [&] { return measure_state(model, state); });
  return run_solver_loop("relax", stop_settings(options), steps, observer, std::move(resumed), started);
}

}  // namespace fabform
