#include "fabform/solver/newton.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "fabform/model/equilibrium.hpp"
#include "fabform/model/potential_energy.hpp"
#include "fabform/solver/contact_move.hpp"
#include "fabform/solver/position_error.hpp"
#include "fabform/solver/solver_loop.hpp"
#include "fabform/solver/solver_registry.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/sparse_diagonal.hpp"
#include "solver/free_directions.hpp"
#include "solver/lagged_friction.hpp"
#include "solver/reduced_hessian.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {

std::string NewtonOptions::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (std::string why = stop_settings(*this).invalid_reason(field); !why.empty()) return why;
  if (!(regularization > 0.0 && regularization <= 1.0))
    return bad("regularization", "must be in (0, 1]");
  if (!(slack_stiffness >= 0.0 && slack_stiffness <= 1.0))
    return bad("slack_stiffness", "must be in [0, 1]: a share of the table's steepest slope");
  if (!(armijo > 0.0 && armijo < 0.5)) return bad("armijo", "must be in (0, 0.5)");
  if (!(max_backtracks >= 1 && max_backtracks <= 200))
    return bad("max_backtracks", "must be between 1 and 200");
  if (!(friction_creep > 0.0 && friction_creep <= 0.1)) return bad("friction_creep", "must be in (0, 0.1]");
  if (LinearMethod method; !linear_method_named(linear_solver, &method))
    return bad("linear_solver", "must be \"auto\", \"cholesky\" or \"multigrid\"");
  return "";
}

namespace {

// Beyond this regularisation (relative to the mean diagonal) the step is a vanishing gradient
// step; a matrix that still fails is broken, not ill-conditioned.
constexpr double kMaxRegularization = 1e8;

// The range of an inexact Newton step's relative tolerance η (NewtonStep::forcing).
constexpr double kMaxForcing = 0.1;
constexpr double kMinForcing = 1e-8;
// A step that left ‖f‖ above this share of the last one's stagnated (NewtonStep::forcing).
constexpr double kStagnantRatio = 0.9;
// A step that measures the distance from the rest (position_error.hpp) is solved at least this
// tightly: every step of a run that stops in metres, and the final estimate's.
constexpr double kMeasuringForcing = 1e-4;
// ... except the final estimate after loose steps, the step over the residual's rate: solved to
// this, its size was within 6 % of the one solved to kMeasuringForcing on the dome at N = 401
// and 0.05 % at N = 1001, in 6 and 4 conjugate-gradient iterations against 16 and 17 (a third
// of the last grid's solve at N = 1001: docs/running.md, "How far from the rest").
constexpr double kEstimateForcing = 1e-2;

// How tightly a step is solved: to the inexact-Newton sequence's η (NewtonStep::forcing) capped
// at `loosest`, or to `loosest` itself when `fixed`; `measuring` takes the exact matrix.
struct StepAccuracy {
  double loosest;
  bool measuring;
  bool fixed;

  /// A step of the sequence, which a run that stops in metres measures (`measuring`).
  static StepAccuracy in_sequence(double loosest, bool measuring) { return {loosest, measuring, false}; }
  /// The final estimate's step after loose steps: to kEstimateForcing, on the exact matrix.
  static StepAccuracy loose_estimate() { return {kEstimateForcing, true, true}; }
};

// Seed 003 §3.2.2: a node on a body whose force (on its free axes) points out of it leaves it.
// On a crease it leaves the face it pulls off and rests on the other, or leaves both.
void release_pulling_nodes(const Model& model, const std::vector<Eigen::Vector3d>& forces,
                           SolverState& state) {
#pragma omp parallel for schedule(static) if (forces.size() >= static_cast<std::size_t>(kMinParallelItems))
  for (std::size_t k = 0; k < forces.size(); ++k) {
    NodeContact& contact = state.contact[k];
    if (!contact.active()) continue;
    if (const Eigen::Vector3d* crease = contact.crease_normal(); crease && model.locks[k] == 0) {
      switch (crease_hold(forces[k], contact.normal, *crease)) {
        case CreaseHold::both: continue;
        case CreaseHold::first: contact.crease.setZero(); continue;
        case CreaseHold::second: contact.normal = *crease, contact.crease.setZero(); continue;
        case CreaseHold::none: contact = NodeContact{}; continue;
      }
    }
    if (remove_locked(forces[k], model.locks[k]).dot(contact.normal) > 0.0) contact = NodeContact{};
  }
}

// R with the friction lagged for this iteration added where a body holds a node.
std::vector<Eigen::Vector3d> with_friction(const Model& model, std::vector<Eigen::Vector3d> forces,
                                           const CoulombFriction& friction, const std::vector<Eigen::Vector3d>& x) {
  if (friction.empty()) return forces;
#pragma omp parallel for schedule(static) if (model.node_count() >= kMinParallelItems)
  for (int k = 0; k < model.node_count(); ++k)
    forces[static_cast<std::size_t>(k)] += friction.force_at(model, x, k, x[static_cast<std::size_t>(k)]);
  return forces;
}

// ∇Π·Δx = −Σ R_k·Δx_k: the energy change a move predicts to first order.
double first_order_change(const std::vector<Eigen::Vector3d>& forces,
                          const std::vector<Eigen::Vector3d>& from,
                          const std::vector<Eigen::Vector3d>& to) {
  double change = 0.0;
  for (std::size_t k = 0; k < forces.size(); ++k) change -= forces[k].dot(to[k] - from[k]);
  return change;
}

// The terms' checks of the steps from `from` (Term::step_check); a term that lets any step has none.
std::vector<std::unique_ptr<StepCheck>> step_checks(const Model& model,
                                                    const std::vector<Eigen::Vector3d>& from) {
  std::vector<std::unique_ptr<StepCheck>> checks;
  for (const auto& term : model.terms)
    if (auto check = term->step_check(model, from)) checks.push_back(std::move(check));
  return checks;
}

bool every_check_admits(const Model& model, const std::vector<std::unique_ptr<StepCheck>>& checks,
                        const std::vector<Eigen::Vector3d>& to) {
  return std::all_of(checks.begin(), checks.end(), [&](const auto& check) { return check->admits(model, to); });
}

// The Newton step from a state: what the line search moves along, and the estimate of the
// state's distance from the rest.
struct Proposal {
  std::vector<Eigen::Vector3d> forces;  // R at the state, lagged friction included
  CoulombFriction friction;
  std::vector<Eigen::Vector3d> steps;   // per node
};

class NewtonStep {
 public:
  NewtonStep(const Model& model, SolverState& state, const NewtonOptions& options)
      : model_(model),
        state_(state),
        options_(options),
        creep_m_(model.has_friction() ? friction_creep_m(model.fabric, options.friction_creep) : 0.0),
        mu_(state.regularization > 0.0 ? state.regularization : options.regularization) {
    linear_method_named(options.linear_solver, &linear_method_);
  }

  /// The Newton step from the current state (nodes its force pulls off a body are released
  /// first, as the step would); none when the matrix gives no descent direction. A step that
  /// measures the distance from the rest (`measuring`) takes the exact matrix: the slack floor
  /// (NewtonOptions::slack_stiffness) would shorten it where the fabric is slack.
  std::optional<Proposal> propose(const StepAccuracy& accuracy) {
    const std::vector<Eigen::Vector3d> stored = node_forces(model_, state_.x);
    release_pulling_nodes(model_, stored, state_);
    Proposal p{{}, lag_friction(model_, state_, stored, creep_m_), {}};
    p.forces = with_friction(model_, stored, p.friction, state_.x);
    const FreeDirections directions = free_directions(model_, state_.contact);
    if (directions.used == 0) return std::nullopt;
    const Eigen::VectorXd f = reduced_forces(directions, p.forces);
    const double slack_share = accuracy.measuring ? 0.0 : options_.slack_stiffness;
    const double eta = accuracy.fixed ? accuracy.loosest : std::min(forcing(f.norm()), accuracy.loosest);
    const auto step = solve(hessian_.assemble(model_, state_.x, directions, p.friction.empty() ? nullptr : &p.friction,
                                              slack_share),
                            f, directions, eta);
    if (!step) return std::nullopt;
    p.steps = node_steps(directions, *step);
    return p;
  }

  /// The largest node move of the step from the current state, solved to kMeasuringForcing, or
  /// to kEstimateForcing after loose steps; the state is left as it is (NaN without a step).
  double next_step_size() {
    const std::vector<NodeContact> contact = state_.contact;
    const std::optional<Proposal> p =
        propose(loose_ ? StepAccuracy::loose_estimate() : StepAccuracy::in_sequence(kMeasuringForcing, true));
    state_.contact = contact;
    return p ? largest_move(p->steps) : std::nan("");
  }

  /// Moves along the proposed step from the current state, whose ‖V‖∞ is `residual`; false when
  /// no step along it is acceptable (the state is then unchanged).
  bool take(const Proposal& p, double residual) {
    const auto alpha = line_search(p.steps, p.forces, p.friction, residual);
    if (!alpha) return false;
    // Levenberg–Marquardt-like: a full step earns less regularisation, a short one more.
    if (*alpha == 1.0) mu_ = std::max(mu_ / 10.0, options_.regularization);
    else if (*alpha < 0.1) mu_ = std::min(mu_ * 10.0, kMaxRegularization);
    state_.regularization = mu_;
    return true;
  }

  /// The linear solver the steps were solved with (none before the first).
  const LinearSolver* linear_solver() const { return linear_.get(); }

  /// Whether a step was solved more loosely than kMeasuringForcing (by an iterative solve), so
  /// that the steps' sizes do not measure the distance from the rest.
  bool steps_were_loose() const { return loose_; }

 private:
  // Inexact Newton (Eisenstat & Walker 1996, choice 2): an iterative solve need only cut the
  // step's residual to η‖f‖, η = 0.9 (‖f‖/‖f_last‖)², loose far from the rest and tightening
  // as the forces fall, which keeps the convergence superlinear without over-solving early.
  double forcing(double force_norm) {
    double eta = kMaxForcing;
    if (last_force_norm_ > 0.0) {
      const double ratio = force_norm / last_force_norm_;
      eta = 0.9 * ratio * ratio;
      // Not down by more than the last η allows, lest one lucky step over-tighten the next.
      const double safeguard = 0.9 * forcing_ * forcing_;
      if (safeguard > 0.1) eta = std::max(eta, safeguard);
      eta = std::clamp(eta, kMinForcing, kMaxForcing);
      // A step that barely cut ‖f‖ asks for η near 0.9, held at the cap: loose steps that
      // barely move the state would go on so to the iteration cap. The second such step in a
      // row gets a tenth of the last η (one alone is common, and tightening then costs more).
      stagnant_steps_ = ratio > kStagnantRatio ? stagnant_steps_ + 1 : 0;
      if (stagnant_steps_ >= 2) eta = std::max(forcing_ / 10.0, kMinForcing);
    }
    last_force_norm_ = force_norm;
    forcing_ = eta;
    return eta;
  }

  // Solves (H + μ·s·I) δ = f, s the mean diagonal of H over the slots with a direction, to the
  // relative tolerance `eta` when the solve is iterative; raises μ until δ is a descent
  // direction. H is regularised in place, from its own diagonal each time.
  std::optional<Eigen::VectorXd> solve(Eigen::SparseMatrix<double> h, const Eigen::VectorXd& f,
                                       const FreeDirections& directions, double eta) {
    const UnknownLayout layout = unknown_layout(directions, model_.fabric);
    if (!linear_)
      linear_ = make_linear_solver(concrete_method(linear_method_, LinearSystemShape{/*unknowns=*/directions.unknowns(),
                                                                                    /*lattice=*/layout.lattice.has_value(),
                                                                                    /*bending=*/model_.resists_bending()}));
    const std::vector<Eigen::Index> on_diagonal = diagonal_positions(h);
    const Eigen::VectorXd diagonal = stored_diagonal(h, on_diagonal);
    const double mean = sum_in_order(diagonal) / directions.used;
    const double scale = mean > 0.0 ? mean : 1.0;
    for (; mu_ <= kMaxRegularization; mu_ *= 10.0) {
      set_shifted_diagonal(h, on_diagonal, diagonal, mu_ * scale);
      if (!linear_->set_matrix(h, layout)) continue;
      Eigen::VectorXd delta = linear_->solve(f, eta);
      loose_ = loose_ || (eta > kMeasuringForcing && linear_->method() != LinearMethod::cholesky);
      if (delta.allFinite() && delta.dot(f) > 0.0) return delta;
    }
    mu_ = kMaxRegularization;
    return std::nullopt;
  }

  SolverState moved(const std::vector<Eigen::Vector3d>& steps, double alpha) const {
    SolverState trial = state_;
// Dynamic: a node on a body costs more than a free one.
#pragma omp parallel for schedule(dynamic, 256) if (model_.node_count() >= kMinParallelItems)
    for (int k = 0; k < model_.node_count(); ++k) {
      const auto i = static_cast<std::size_t>(k);
      const NodeMove m = move_node(model_, k, state_.x[i], alpha * steps[i], state_.contact[i], Valleys::both_faces);
      trial.x[i] = m.x;
      trial.contact[i] = m.contact;
    }
    return trial;
  }

  // Backtracking from the full step. Near the solution the energy's change falls below its
  // rounding (~1e-11 of the total); there a step is judged by whether it lowers ‖V‖∞ instead.
  std::optional<double> line_search(const std::vector<Eigen::Vector3d>& steps,
                                    const std::vector<Eigen::Vector3d>& forces, const CoulombFriction& friction,
                                    double residual) {
    // Π's change, each term's its own way; the energy the fabric stores sets its rounding.
    const EnergyBaseline baseline = energy_baseline(model_, state_.x);
    const double noise = 1e-11 * std::abs(baseline.stored);
    const double friction_before = friction.empty() ? 0.0 : friction.energy(model_, state_.x);
    const std::vector<std::unique_ptr<StepCheck>> checks = step_checks(model_, state_.x);
    double alpha = 1.0;
    for (int t = 0; t <= options_.max_backtracks; ++t, alpha *= 0.5) {
      SolverState trial = moved(steps, alpha);
      if (!every_check_admits(model_, checks, trial.x)) continue;
      const double change = energy_change(model_, state_.x, baseline, trial.x) +
                            (friction.empty() ? 0.0 : friction.energy(model_, trial.x) - friction_before);
      const double predicted = first_order_change(forces, state_.x, trial.x);
      const bool decreases = change < 0.0 && change <= options_.armijo * std::min(predicted, 0.0);
      if (decreases || (std::abs(change) <= noise &&
                        measure_state(model_, trial).max_residual_N < residual)) {
        state_ = std::move(trial);
        return alpha;
      }
    }
    return std::nullopt;
  }

  const Model& model_;
  SolverState& state_;
  const NewtonOptions& options_;
  double creep_m_;  // friction's creep length ε (0 without friction)
  double mu_;  // current regularisation, relative to the mean diagonal
  LinearMethod linear_method_;
  std::unique_ptr<LinearSolver> linear_;  // chosen at the first step, by its unknowns
  ReducedHessian hessian_;  // keeps the matrix's pattern from step to step
  double last_force_norm_ = 0.0;  // ‖f‖₂ of the last step proposed (0: none yet)
  double forcing_ = kMaxForcing;  // its η
  int stagnant_steps_ = 0;  // steps in a row whose ‖f‖ stayed above kStagnantRatio of the last
  bool loose_ = false;  // see steps_were_loose
};

void record_linear_solver(Summary& summary, const NewtonStep& step) {
  if (const LinearSolver* linear = step.linear_solver()) {
    summary.linear_solver = linear->name();
    summary.linear_iterations = linear->iterations();
  }
}

std::string stall_message(const Summary& s) {
  std::ostringstream text;
  text.precision(3);
  text << "line search stalled after " << s.iterations << " iterations with ||V||inf = "
       << s.residual_N << " N > e = " << s.tolerance_N
       << " N: no step along the Newton direction lowers the energy (worst node " << s.worst_node
       << ")";
  return text.str();
}

}  // namespace

Summary newton(const Model& model, SolverState& state, const NewtonOptions& options,
               const IterationObserver& observer, Summary resumed) {
  if (const std::string why = options.invalid_reason(); !why.empty())
    throw std::invalid_argument("newton: " + why);
  if (const std::string why = solver_refusal(model, "newton"); !why.empty())
    throw std::invalid_argument("newton: " + why);
  const auto started = std::chrono::steady_clock::now();
  NewtonStep step(model, state, options);
  std::vector<double> step_sizes;  // of the steps proposed from each state in turn
  // Stopping in metres, each step measures the distance from the rest.
  const double loosest = options.tolerance_m > 0.0 ? kMeasuringForcing : kMaxForcing;
  SolverSteps steps;
  steps.step = [&](Summary& summary) {
    // The step from the state last recorded measures its distance from the rest. Proposing
    // releases nodes that pull off a body; a run that stops here keeps the state's own contact.
    std::vector<NodeContact> contact;
    if (options.tolerance_m > 0.0) contact = state.contact;
    const std::optional<Proposal> proposal = step.propose(StepAccuracy::in_sequence(loosest, options.tolerance_m > 0.0));
    step_sizes.push_back(proposal ? largest_move(proposal->steps) : std::nan(""));
    const double distance = step.steps_were_loose() ? std::nan("") : newton_position_error(step_sizes);
    if (options.tolerance_m > 0.0 && record_position_error(summary, distance)) {
      state.contact = std::move(contact);
      return StepOutcome::stopped;
    }
    if (proposal && step.take(*proposal, summary.residual_N)) return StepOutcome::moved;
    summary.position_error_m = distance;  // the state stays where it was measured
    return StepOutcome::stalled;
  };
  steps.measure = [&] { return measure_state(model, state); };
  // One more factorisation (or solve), of the final state, without moving it.
  if (options.final_estimate)
    steps.final_position_error = [&](const Summary& summary) {
      const double size = step.next_step_size();
      if (step.steps_were_loose()) return inexact_newton_position_error(size, summary.history);
      step_sizes.push_back(size);
      return newton_position_error(step_sizes);
    };
  steps.stall_message = stall_message;
  Summary summary = run_solver_loop("newton", stop_settings(options), steps, observer, std::move(resumed), started);
  record_linear_solver(summary, step);
  return summary;
}

}  // namespace fabform
