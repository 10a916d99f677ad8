// The pressure term (model/pressure.hpp) checked as every term is, by central differences, on a
// clamped fabric bulged out of its plane: its force is minus its energy's gradient, its exact
// Hessian (the side couplings) minus its force's derivative, and what Newton takes of it is
// positive semi-definite. Inside the fabric its force is the follower load, −P times a third of
// the node's triangles' vector areas, whatever the reference point.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "fabform/model/pressure.hpp"
#include "support/clamped_fabric.hpp"
#include "support/term_checks.hpp"

namespace fabform::pressure_test {
namespace {

constexpr double kPressure_Pa = 2500.0;

// A 4 × 4 clamped fabric, bulged and warped so that no face is flat.
Model bulged_fabric() {
  Model model = test::clamped_fabric(4);
  for (int k = 0; k < model.node_count(); ++k) {
    Eigen::Vector3d& p = model.start[static_cast<std::size_t>(k)];
    p.z() = 0.02 * std::sin(31.4 * p.x()) * std::sin(31.4 * p.y()) + 0.003 * std::cos(97.0 * p.x() + 53.0 * p.y());
    p.x() += 0.002 * std::sin(71.0 * p.y());
  }
  return model;
}

Eigen::Vector3d centroid(const Positions& x) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : x) sum += p;
  return sum / static_cast<double>(x.size());
}

TEST(PressureLoad, ForceIsMinusTheGradientOfItsEnergy) {
  const Model model = bulged_fabric();
  const PressureLoad load(model.fabric, kPressure_Pa, centroid(model.start));
  test::expect_force_is_minus_the_gradient(model, load, model.start, 1e-7, 1e-7);
}

TEST(PressureLoad, NodeChangesAreTheWholeEnergysChange) {
  const Model model = bulged_fabric();
  const PressureLoad load(model.fabric, kPressure_Pa, centroid(model.start));
  test::expect_node_changes_are_the_whole(model, load, model.start, {6, 12, 18}, Eigen::Vector3d(1e-4, -2e-4, 3e-4));
}

TEST(PressureLoad, SideCouplingsAreMinusTheForcesDerivative) {
  const Model model = bulged_fabric();
  const PressureLoad load(model.fabric, kPressure_Pa, centroid(model.start));
  const int n = model.node_count();
  Eigen::MatrixXd exact = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (const PressureCoupling& c : load.couplings(model.start)) {
    Eigen::Matrix3d s;
    s << 0.0, -c.s.z(), c.s.y(), c.s.z(), 0.0, -c.s.x(), -c.s.y(), c.s.x(), 0.0;
    exact.block<3, 3>(3 * c.a, 3 * c.b) += s;
    exact.block<3, 3>(3 * c.b, 3 * c.a) += s.transpose();
  }
  const double h = 1e-7;
  for (int k = 0; k < n; ++k)
    for (int axis = 0; axis < 3; ++axis) {
      Positions plus = model.start, minus = model.start;
      plus[static_cast<std::size_t>(k)][axis] += h, minus[static_cast<std::size_t>(k)][axis] -= h;
      for (int j = 0; j < n; ++j) {
        // The force is linear in each other node, so central differences are exact to rounding.
        const Eigen::Vector3d derivative = -(load.force_at(model, plus, j, plus[static_cast<std::size_t>(j)]) -
                                             load.force_at(model, minus, j, minus[static_cast<std::size_t>(j)])) /
                                           (2.0 * h);
        const Eigen::Vector3d column = exact.block<3, 1>(3 * j, 3 * k + axis);
        EXPECT_LT((derivative - column).norm(), 1e-6 * kPressure_Pa * 0.025) << j << " by " << k << "/" << axis;
      }
    }
}

TEST(PressureLoad, NewtonsPartIsPositiveSemiDefinite) {
  const Model model = bulged_fabric();
  const PressureLoad load(model.fabric, kPressure_Pa, centroid(model.start));
  const Eigen::MatrixXd k = test::dense_stiffness(model, load, model.start);
  const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues().minCoeff();
  EXPECT_GE(smallest, -1e-12 * k.cwiseAbs().maxCoeff());
  EXPECT_GT(k.cwiseAbs().maxCoeff(), 0.0);
}

// The follower load at an inner node: −P/3 Σ A_t n_t over its triangles, each four-sided face
// counted as its two splittings at half weight; the same from any reference point.
TEST(PressureLoad, InnerNodesFeelTheFollowerLoadFromAnyReference) {
  const Model model = bulged_fabric();
  const PressureLoad near(model.fabric, kPressure_Pa, centroid(model.start));
  const PressureLoad far(model.fabric, kPressure_Pa, Eigen::Vector3d(3.0, -7.0, 11.0));
  const Positions& x = model.start;
  for (int k = 0; k < model.node_count(); ++k) {
    if (model.fabric.on_perimeter(k)) continue;
    Eigen::Vector3d expected = Eigen::Vector3d::Zero();
    for (const int f : model.fabric.faces_at(k)) {
      const auto& c = model.fabric.faces()[static_cast<std::size_t>(f)].corner;
      const auto p = [&](int i) { return x[static_cast<std::size_t>(c[static_cast<std::size_t>(i)])]; };
      const std::array<std::array<int, 3>, 4> splits = {{{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 2, 3}}};
      for (const auto& t : splits)
        if (c[static_cast<std::size_t>(t[0])] == k || c[static_cast<std::size_t>(t[1])] == k ||
            c[static_cast<std::size_t>(t[2])] == k)
          expected -= kPressure_Pa / 3.0 * 0.5 * 0.5 * (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]));
    }
    const Eigen::Vector3d at_near = near.force_at(model, x, k, x[static_cast<std::size_t>(k)]);
    const Eigen::Vector3d at_far = far.force_at(model, x, k, x[static_cast<std::size_t>(k)]);
    EXPECT_LT((at_near - expected).norm(), 1e-12 * expected.norm()) << k;
    EXPECT_LT((at_far - expected).norm(), 1e-10 * expected.norm()) << k;
  }
}

// Flat and face up, a positive pressure pushes each inner node down by P times its area.
TEST(PressureLoad, PushesAFlatFabricDownByItsArea) {
  const Model model = test::clamped_fabric(4);
  const PressureLoad load(model.fabric, kPressure_Pa, centroid(model.start));
  const std::vector<double> area = model.fabric.node_areas();
  for (int k = 0; k < model.node_count(); ++k) {
    if (model.fabric.on_perimeter(k)) continue;
    const Eigen::Vector3d f = load.force_at(model, model.start, k, model.start[static_cast<std::size_t>(k)]);
    EXPECT_NEAR(f.z(), -kPressure_Pa * area[static_cast<std::size_t>(k)], 1e-12 * kPressure_Pa * area[static_cast<std::size_t>(k)]);
    EXPECT_NEAR(f.head<2>().norm(), 0.0, 1e-12 * kPressure_Pa * area[static_cast<std::size_t>(k)]);
  }
}

}  // namespace
}  // namespace fabform::pressure_test
