#pragma once
// What every term of the model must satisfy, checked by central differences: its force is minus
// the gradient of its energy, its change for one node's move is its whole energy's change, and
// its stiffness is minus the derivative of its force (where the term's stiffness is exact).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform::test {

/// −∂Π_t/∂x_k against force_at at every node and axis, within `tolerance` × the largest force.
inline void expect_force_is_minus_the_gradient(const Model& model, const Term& term, const Positions& x,
                                               double step_m, double tolerance) {
  double largest = 0.0;
  for (int k = 0; k < model.node_count(); ++k)
    largest = std::max(largest, term.force_at(model, x, k, x[static_cast<std::size_t>(k)]).norm());
  ASSERT_GT(largest, 0.0) << "the check needs a state where the term pushes";
  for (int k = 0; k < model.node_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    const Eigen::Vector3d force = term.force_at(model, x, k, x[i]);
    for (int axis = 0; axis < 3; ++axis) {
      Positions plus = x, minus = x;
      plus[i][axis] += step_m, minus[i][axis] -= step_m;
      const double slope = (term.energy(model, plus) - term.energy(model, minus)) / (2.0 * step_m);
      EXPECT_NEAR(-slope, force[axis], tolerance * largest) << "node " << k << " axis " << axis;
    }
  }
}

/// node_energy_change against the change of the whole energy, and energy_change against the
/// difference of energies, for one node's move.
inline void expect_node_changes_are_the_whole(const Model& model, const Term& term, const Positions& x,
                                              std::initializer_list<int> nodes, const Eigen::Vector3d& move) {
  const double before = term.energy(model, x);
  for (const int k : nodes) {
    Positions moved = x;
    moved[static_cast<std::size_t>(k)] += move;
    const double whole = term.energy(model, moved) - before;
    ASSERT_NE(whole, 0.0) << "node " << k << ": the move should change the term's energy";
    const double scale = 1e-9 * std::max(std::abs(whole), 1e-9 * std::abs(before));
    EXPECT_NEAR(term.node_energy_change(model, x, k, moved[static_cast<std::size_t>(k)]), whole, scale) << k;
    EXPECT_NEAR(term.energy_change(model, x, before, moved), whole, scale) << k;
  }
}

/// The term's stiffness as a dense 3n × 3n matrix.
inline Eigen::MatrixXd dense_stiffness(const Model& model, const Term& term, const Positions& x) {
  class Dense final : public StiffnessSink {
   public:
    explicit Dense(int nodes) : matrix(Eigen::MatrixXd::Zero(3 * nodes, 3 * nodes)) {}
    void add(int row, int col, const Eigen::Matrix3d& k) override {
      matrix.block<3, 3>(3 * row, 3 * col) += k;
      if (row != col) matrix.block<3, 3>(3 * col, 3 * row) += k.transpose();
    }
    Eigen::MatrixXd matrix;
  } dense(model.node_count());
  term.add_stiffness(model, x, dense);
  return dense.matrix;
}

/// −∂F/∂x by central differences against add_stiffness, within `tolerance` × its largest entry.
inline void expect_stiffness_is_minus_the_force_derivative(const Model& model, const Term& term, const Positions& x,
                                                           double step_m, double tolerance) {
  const Eigen::MatrixXd stiffness = dense_stiffness(model, term, x);
  const double scale = stiffness.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  const auto forces = [&](const Positions& at) {
    Eigen::VectorXd f(3 * model.node_count());
    for (int k = 0; k < model.node_count(); ++k)
      f.segment<3>(3 * k) = term.force_at(model, at, k, at[static_cast<std::size_t>(k)]);
    return f;
  };
  for (int k = 0; k < model.node_count(); ++k)
    for (int axis = 0; axis < 3; ++axis) {
      Positions plus = x, minus = x;
      plus[static_cast<std::size_t>(k)][axis] += step_m, minus[static_cast<std::size_t>(k)][axis] -= step_m;
      const Eigen::VectorXd column = -(forces(plus) - forces(minus)) / (2.0 * step_m);
      EXPECT_LT((column - stiffness.col(3 * k + axis)).cwiseAbs().maxCoeff(), tolerance * scale)
          << "node " << k << " axis " << axis;
    }
}

}  // namespace fabform::test
