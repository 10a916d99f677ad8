// The energy check (energy_consistency.hpp) on a clamped fabric lifted in its middle: its springs'
// energy agrees with their forces at every free node; a load whose force is thrice its energy's
// derivative disagrees at every node it pulls, and is named; an energy that jumps at one node's
// place is found there; a force without a potential is refused.
#include "fabform/analysis/energy_consistency.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "support/clamped_fabric.hpp"

namespace fabform::energy_consistency_test {
namespace {

// Π = −F Σ z, with a force of `force_share` times its derivative, F ẑ.
class Lift final : public Term {
 public:
  Lift(double force_N, double force_share) : force_N_(force_N), share_(force_share) {}
  std::string describe(const Model&) const override { return "lift: a test's load"; }
  Eigen::Vector3d force_at(const Model&, const Positions&, int, const Eigen::Vector3d&) const override {
    return Eigen::Vector3d(0.0, 0.0, share_ * force_N_);
  }
  double energy(const Model&, const Positions& x) const override {
    double sum = 0.0;
    for (const Eigen::Vector3d& p : x) sum -= force_N_ * p.z();
    return sum;
  }
  double node_energy_change(const Model&, const Positions& x, int node, const Eigen::Vector3d& at) const override {
    return -force_N_ * (at.z() - x[static_cast<std::size_t>(node)].z());
  }

 private:
  double force_N_;
  double share_;
};

// Π = J once node `node` lies past `from` along x, 0 before: a wall the line search cannot cross.
class Step final : public Term {
 public:
  Step(int node, double from) : node_(node), from_(from) {}
  std::string describe(const Model&) const override { return "step: a test's jump"; }
  Eigen::Vector3d force_at(const Model&, const Positions&, int, const Eigen::Vector3d&) const override {
    return Eigen::Vector3d::Zero();
  }
  double energy(const Model&, const Positions& x) const override { return value(x[static_cast<std::size_t>(node_)]); }
  double node_energy_change(const Model&, const Positions& x, int node, const Eigen::Vector3d& at) const override {
    return node == node_ ? value(at) - value(x[static_cast<std::size_t>(node)]) : 0.0;
  }

 private:
  double value(const Eigen::Vector3d& p) const { return p.x() > from_ ? 0.01 : 0.0; }
  int node_;
  double from_;
};

class Drag final : public Term {
 public:
  std::string describe(const Model&) const override { return "drag"; }
  Eigen::Vector3d force_at(const Model&, const Positions&, int, const Eigen::Vector3d&) const override {
    return Eigen::Vector3d::Zero();
  }
  double energy(const Model&, const Positions&) const override { return 0.0; }
  double node_energy_change(const Model&, const Positions&, int, const Eigen::Vector3d&) const override { return 0.0; }
  SolverNeeds needs() const override { return SolverNeed::velocity; }
};

Model lifted_fabric() {
  Model model = test::clamped_fabric(8, 0.01);
  test::lift_interior(model, 0.01);
  return model;
}

TEST(EnergyConsistency, TheSpringsAgreeWithTheirForces) {
  const Model model = lifted_fabric();
  const EnergyConsistency result = check_energy_consistency(model, SolverState::at_start(model));
  EXPECT_GT(result.checked, 20);  // the ring next to the held edge; the middle lies level
  EXPECT_TRUE(result.disagreeing.empty());
}

TEST(EnergyConsistency, AForceThatIsNotItsEnergysDerivativeIsNamedAtEveryNode) {
  Model model = lifted_fabric();
  // Thrice its derivative, 1 kN up: far above the springs' pull, so every free node is checked and
  // its change is a third of the prediction's (a share of a half is the threshold).
  model.terms.push_back(std::make_shared<Lift>(1000.0, 3.0));
  const EnergyConsistency result = check_energy_consistency(model, SolverState::at_start(model));
  EXPECT_EQ(result.checked, 49);  // the 7 × 7 free nodes
  ASSERT_EQ(result.disagreeing.size(), 49u);
  for (const EnergyDisagreement& d : result.disagreeing) EXPECT_EQ(d.term, "lift") << d.node;
  // A force that is its energy's derivative agrees.
  Model right = lifted_fabric();
  right.terms.push_back(std::make_shared<Lift>(1000.0, 1.0));
  EXPECT_TRUE(check_energy_consistency(right, SolverState::at_start(right)).disagreeing.empty());
}

TEST(EnergyConsistency, AnEnergyThatJumpsAtANodesPlaceIsFoundThere) {
  // The middle node moved 2 mm along x: its springs pull it back along −x, across a wall 1e-10 m
  // behind it where Π falls by 0.01 J; no other node moves the wall.
  Model model = lifted_fabric();
  const int node = 4 * 9 + 4;
  model.start[static_cast<std::size_t>(node)].x() += 0.002;
  model.terms.push_back(std::make_shared<Step>(node, model.start[static_cast<std::size_t>(node)].x() - 1e-10));
  const EnergyConsistency result = check_energy_consistency(model, SolverState::at_start(model));
  ASSERT_EQ(result.disagreeing.size(), 1u);
  EXPECT_EQ(result.disagreeing.front().node, node);
  EXPECT_EQ(result.disagreeing.front().term, "step");
  EXPECT_NEAR(result.disagreeing.front().measured_J, -0.005, 1e-6);  // half the wall's 0.01 J
}

TEST(EnergyConsistency, AForceWithoutAPotentialIsRefused) {
  Model model = lifted_fabric();
  model.terms.push_back(std::make_shared<Drag>());
  EXPECT_THROW(check_energy_consistency(model, SolverState::at_start(model)), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::energy_consistency_test
