#pragma once
// One physical term of the model (the fabric's springs, its hinges, its weight, the wind, ...):
// its force on a node, its potential, its stiffness and what it asks of a solver, behind one
// interface. The model holds its terms in a list (model.hpp) and every solver walks that list
// without naming a term, so a new term is a new file, not an edit in each solver.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/node_set.hpp"
#include "fabform/model/solver_needs.hpp"

namespace fabform {

struct Model;
using Positions = std::vector<Eigen::Vector3d>;

/// Receives a term's stiffness ∂²Π/∂x² block by block.
class StiffnessSink {
 public:
  virtual ~StiffnessSink() = default;
  /// Adds K to the block coupling nodes `row` and `col` and, when they differ, Kᵀ to the
  /// block (col, row): a term hands each pair once.
  virtual void add(int row, int col, const Eigen::Matrix3d& stiffness) = 0;
  /// A slack spring's stiffness is zero; a step's matrix may take this share of its table's
  /// steepest slope along it instead (spring_energy.hpp). 0: the energy's own second derivative.
  virtual double slack_share() const { return 0.0; }
  /// Item k's blocks for k = 0 … count − 1, `each(k, sink)` adding them. A sink may run the items
  /// on several threads, each into a sink of its own that keeps a share of the pairs, every one
  /// over all items in order: `each` must only add, and then each pair's blocks are summed in the
  /// order the serial loop sums them, whatever the threads.
  virtual void add_each(std::size_t count, const std::function<void(std::size_t, StiffnessSink&)>& each) {
    for (std::size_t k = 0; k < count; ++k) each(k, *this);
  }
};

/// What bounds an explicit time step: per node, half the sum of the absolute stiffness in its
/// rows (a spring of stiffness k adds k to each end), and the stiffest single element.
struct StiffnessBound {
  std::vector<double> per_node;  // N/m
  double stiffest_element = 0.0;  // N/m
};

/// The directions a node may move in: its free axes and, on a body, the tangent plane.
struct NodeFreedom {
  AxisMask locks = 0;
  const Eigen::Vector3d* contact_normal = nullptr;  // the body's normal, when on one
  /// v within those directions (a node on a body loses the part along its normal).
  Eigen::Vector3d project(const Eigen::Vector3d& v) const;
};

/// A velocity-dependent force over one time step of `dynamic`, taken implicitly so that it
/// never limits the step.
class StepDrag {
 public:
  virtual ~StepDrag() = default;
  /// The node's velocity after a step of `seconds` under this force alone; the result stays
  /// within `freedom`.
  virtual Eigen::Vector3d after(int node, double seconds, double mass_kg, const Eigen::Vector3d& velocity,
                                const NodeFreedom& freedom) const = 0;
};

/// Which moves of the fabric from one state a solver's step may make at once (Term::step_check).
class StepCheck {
 public:
  virtual ~StepCheck() = default;
  /// Whether the step may carry the fabric from the checked state to `to` at once.
  virtual bool admits(const Model& model, const Positions& to) const = 0;
};

class Term {
 public:
  virtual ~Term() = default;

  /// One line for result.json's "modelled": what the term is, with its values.
  virtual std::string describe(const Model& model) const = 0;

  /// The term's force on `node` placed at `at`, every other node where x has it (N). For a
  /// velocity-dependent term, its force on the fabric at rest.
  virtual Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                                   const Eigen::Vector3d& at) const = 0;

  /// Adds its force on every node at x (force_at at each node's own place) to `forces`. A term
  /// whose forces come from pairs found over the whole fabric finds them once here.
  virtual void add_forces(const Model& model, const Positions& x, std::vector<Eigen::Vector3d>& forces) const;

  /// Its potential Π_t(x) (J), whose −gradient is force_at; 0 for a term without one.
  virtual double energy(const Model& model, const Positions& x) const = 0;

  /// Π_t(to) − Π_t(from), given Π_t(from) = energy(from). A load's potential computes it from
  /// the moves, so it keeps its digits however high the fabric sits.
  virtual double energy_change(const Model& model, const Positions& /*from*/, double from_energy,
                               const Positions& to) const {
    return energy(model, to) - from_energy;
  }

  /// Π_t's change when `node` alone moves from x[node] to `at`.
  virtual double node_energy_change(const Model& model, const Positions& x, int node,
                                    const Eigen::Vector3d& at) const = 0;

  /// Adds ∂²Π_t/∂x², made positive semi-definite where it is not, for Newton's method.
  virtual void add_stiffness(const Model& /*model*/, const Positions& /*x*/, StiffnessSink& /*sink*/) const {}

  /// Adds a bound of the term's stiffness at any positions, for dynamic's stable time step.
  virtual void bound_stiffness(const Model& /*model*/, StiffnessBound& /*bound*/) const {}

  /// The term's velocity-dependent part for a step starting at x; null when it has none.
  virtual std::unique_ptr<StepDrag> drag(const Model& /*model*/, const Positions& /*x*/) const {
    return nullptr;
  }

  /// Which steps from `from` the term lets a solver take at once; null when it lets any. A stiff
  /// contact penalty refuses a step that would take a spring deep into a body in one go (say
  /// through a thin wall, which no penalty undoes); the step is then shortened.
  virtual std::unique_ptr<StepCheck> step_check(const Model& /*model*/, const Positions& /*from*/) const {
    return nullptr;
  }

  /// An external load (its potential is the work against it), not energy the fabric stores.
  virtual bool external() const { return false; }

  /// The term resists folding (a fabric compressed flat then says bending did not stop it).
  virtual bool resists_bending() const { return false; }

  /// What the term asks of the solver that carries it (solver_needs.hpp); none by default.
  virtual SolverNeeds needs() const { return {}; }

  /// A warning when tolerance e is too coarse for the term to show in a run, or "".
  virtual std::string tolerance_warning(double /*tolerance_N*/) const { return ""; }
};

using TermList = std::vector<std::shared_ptr<const Term>>;

}  // namespace fabform
