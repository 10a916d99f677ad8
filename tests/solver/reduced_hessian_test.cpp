// Newton's matrix against central differences of the node forces, on a taut fabric (every
// spring stretched, so projecting a spring's stiffness changes nothing) with hinges bent out of
// its plane: springs and hinges together, in the free directions of the unlocked nodes.
#include "solver/reduced_hessian.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "fabform/model/hinge_bending.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform {
namespace {

Model bent_hinged_fabric() {
  FabricSpec spec{0.1, 0.1, 4, 4};
  spec.hinges = true;
  Model model = test::clamped_fabric(4, 0.05);
  model.fabric = Fabric(spec);
  model.terms.push_back(std::make_shared<HingeBending>(2e-3));
  std::mt19937 rng(11u);
  std::uniform_real_distribution<double> lift(-0.002, 0.002);
  for (int k = 0; k < model.node_count(); ++k)
    if (!model.fabric.on_perimeter(k)) model.start[static_cast<std::size_t>(k)].z() += lift(rng);
  return model;
}

Eigen::VectorXd forces_at(const Model& model, const FreeDirections& d, const std::vector<Eigen::Vector3d>& x) {
  std::vector<Eigen::Vector3d> f;
  for (int k = 0; k < model.node_count(); ++k) f.push_back(node_force(model, x, k));
  return reduced_forces(d, f);
}

// Step 1e-7 m on node spacings of 2.5 cm: truncation ~h²·f''' and rounding ~ε·f/h both stay
// below 1e-6 of the matrix's largest entry.
TEST(ReducedHessian, IsMinusTheDerivativeOfTheNodeForces) {
  const Model model = bent_hinged_fabric();
  const std::vector<Eigen::Vector3d>& x = model.start;
  const FreeDirections d = free_directions(model, std::vector<NodeContact>(x.size()));
  ASSERT_GT(d.unknowns(), 0);
  const Eigen::MatrixXd lower(reduced_hessian(model, x, d));
  const Eigen::MatrixXd h = lower + lower.transpose() - Eigen::MatrixXd(lower.diagonal().asDiagonal());
  const double scale = h.cwiseAbs().maxCoeff();
  const double step = 1e-7;
  for (int k = 0; k < model.node_count(); ++k)
    for (int c = 0; c < d.count(k); ++c) {
      std::vector<Eigen::Vector3d> plus = x, minus = x;
      plus[static_cast<std::size_t>(k)] += step * d.of(k).col(c);
      minus[static_cast<std::size_t>(k)] -= step * d.of(k).col(c);
      const Eigen::VectorXd column = -(forces_at(model, d, plus) - forces_at(model, d, minus)) / (2.0 * step);
      EXPECT_LT((column - h.col(d.offset[static_cast<std::size_t>(k)] + c)).cwiseAbs().maxCoeff(), 1e-6 * scale)
          << "node " << k << " direction " << c;
    }
}

// Without hinges the springs alone; the hinges add to it (a check that they are in at all).
TEST(ReducedHessian, HingesAddTheirStiffness) {
  Model model = bent_hinged_fabric();
  const FreeDirections d = free_directions(model, std::vector<NodeContact>(model.start.size()));
  const Eigen::MatrixXd with(reduced_hessian(model, model.start, d));
  model.terms.pop_back();
  const Eigen::MatrixXd without(reduced_hessian(model, model.start, d));
  EXPECT_GT((with - without).cwiseAbs().maxCoeff(), 1e-3 * without.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace fabform
