// Edge contact (edge_contact.hpp): the depth a segment reaches under a convex edge against a brute
// force over the segment's points (the depth of a point in a wedge is its distance to the nearer
// face), the penalty's gradient against central differences of its energy, swept over edges of
// every sharpness and segments crossing them everywhere (past the ends too, where the weight
// falls), and the term's forces against differences of the term's energy on a strip over a cube.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fabform/model/edge_contact.hpp"
#include "fabform/model/model.hpp"
#include "support/clamped_fabric.hpp"
#include "support/shapes.hpp"

namespace fabform::edge_contact_test {
namespace {

// An edge along y from (0, 0, 0) to (0, 1, 0) whose faces turn by `angle` (radians) between them,
// symmetric about +z: the body lies below both.
SharpEdge edge_turning_by(double angle) {
  const double half = 0.5 * angle;
  return {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), Eigen::Vector3d(-std::sin(half), 0.0, std::cos(half)),
          Eigen::Vector3d(std::sin(half), 0.0, std::cos(half))};
}

// An edge continued at both ends, whose wedge reaches 0.1 past them.
const EdgeEnds open_ends{false, false, 0.1};

double wedge_depth(const SharpEdge& e, const Eigen::Vector3d& p) {
  return std::min(-(p - e.from).dot(e.normal_a), -(p - e.from).dot(e.normal_b));
}

TEST(EdgeContact, TheReachIsTheDeepestPointOfTheSegmentInTheWedge) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> across(-1.0, 1.0), along(0.1, 0.9);
  int checked = 0;
  for (const double degrees : {5.0, 30.0, 90.0, 150.0}) {
    const SharpEdge edge = edge_turning_by(degrees * M_PI / 180.0);
    for (int trial = 0; trial < 200; ++trial) {
      const Eigen::Vector3d a(-1.0 + 0.3 * across(random), along(random), 0.2 * across(random));
      const Eigen::Vector3d b(1.0 + 0.3 * across(random), along(random), 0.2 * across(random));
      // The nodes at a spring's ends are outside the body (node contact keeps them so).
      if (wedge_depth(edge, a) > 0.0 || wedge_depth(edge, b) > 0.0) continue;
      double deepest = -1e9;
      for (int k = 0; k <= 200000; ++k) deepest = std::max(deepest, wedge_depth(edge, a + (k / 200000.0) * (b - a)));
      const auto reach = reach_under_edge(edge, a, b, open_ends);
      if (deepest <= 0.0) {
        EXPECT_FALSE(reach.has_value());
        continue;
      }
      ASSERT_TRUE(reach.has_value()) << degrees << " " << trial;
      // The sampled maximum is below the true one by at most the sampling step times the slope.
      EXPECT_NEAR(reach->depth, deepest, 3.0 * (b - a).norm() / 200000.0) << degrees;
      EXPECT_GE(reach->depth, deepest - 1e-12);
      EXPECT_EQ(reach->weight, 1.0);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);  // the sweep did reach under the edges
}

TEST(EdgeContact, ASegmentAboveTheFacesOrFarBelowTheEdgeDoesNotReach) {
  const SharpEdge edge = edge_turning_by(M_PI / 2.0);
  EXPECT_FALSE(reach_under_edge(edge, Eigen::Vector3d(-1, 0.5, 0.01), Eigen::Vector3d(1, 0.5, 0.01), open_ends));
  // Under the edge by more than its own length: under another part of the body, not this corner.
  EXPECT_FALSE(reach_under_edge(edge, Eigen::Vector3d(-0.1, 0.5, -1.0), Eigen::Vector3d(0.1, 0.5, -1.0), open_ends));
  // Parallel to the bisecting plane: along the edge.
  EXPECT_FALSE(reach_under_edge(edge, Eigen::Vector3d(0, 0.2, -0.01), Eigen::Vector3d(0, 0.8, -0.01), open_ends));
}

// Central differences with a step of 1e-7 of the segment's scale, swept over edges whose ends
// continue (the weight falls past them) and edges whose ends are corners (the depth is capped by
// the distance to the end): away from the cap's switch the penalty is smooth, so the truncation
// error is O(h²) times its third derivative.
TEST(EdgeContact, ThePenaltysGradientIsItsEnergysDerivative) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double stiffness = 1e4, h = 1e-7;
  int checked = 0, weighted = 0, capped = 0;
  for (const EdgeEnds ends : {EdgeEnds{false, false, 0.2}, EdgeEnds{true, true, 0.2}})
    for (const double degrees : {10.0, 90.0, 140.0}) {
      const SharpEdge edge = edge_turning_by(degrees * M_PI / 180.0);
      for (int trial = 0; trial < 300; ++trial) {
        // Across the edge anywhere from 0.2 before its start to 0.2 past its end.
        const Eigen::Vector3d a(-0.5 + 0.1 * u(random), 0.5 + 0.7 * u(random), -0.05 + 0.05 * u(random));
        const Eigen::Vector3d b(0.5 + 0.1 * u(random), 0.5 + 0.7 * u(random), -0.05 + 0.05 * u(random));
        const auto reach = reach_under_edge(edge, a, b, ends);
        if (!reach) continue;
        const Eigen::Vector3d p = a + reach->along * (b - a);
        const double to_end = std::min(p.y(), 1.0 - p.y());
        if (ends.capped_from && std::abs(to_end - wedge_depth(edge, p)) < 1e-4) continue;  // at the switch
        const EdgePenalty penalty = edge_penalty(*reach, stiffness, 0.01);
        const auto energy = [&](const Eigen::Vector3d& pa, const Eigen::Vector3d& pb) {
          const auto r = reach_under_edge(edge, pa, pb, ends);
          return r ? edge_penalty(*r, stiffness, 0.01).energy : 0.0;
        };
        const double scale = penalty.gradient_a.norm() + penalty.gradient_b.norm();
        for (int axis = 0; axis < 3; ++axis) {
          const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(axis);
          const double da = (energy(a + step, b) - energy(a - step, b)) / (2 * h);
          const double db = (energy(a, b + step) - energy(a, b - step)) / (2 * h);
          EXPECT_NEAR(penalty.gradient_a[axis], da, 1e-5 * scale + 1e-9) << degrees << " " << trial;
          EXPECT_NEAR(penalty.gradient_b[axis], db, 1e-5 * scale + 1e-9) << degrees << " " << trial;
        }
        ++checked;
        weighted += reach->weight < 1.0 ? 1 : 0;
        if (ends.capped_from) {
          EXPECT_LE(reach->depth, to_end + 1e-15);  // no deeper than the corner is near
          EXPECT_GE(to_end, 0.0);                   // and none past it
          capped += reach->depth < wedge_depth(edge, p) ? 1 : 0;
        }
      }
    }
  EXPECT_GT(checked, 100);
  EXPECT_GT(weighted, 5);  // past continued ends
  EXPECT_GT(capped, 5);    // near corners
}

// A strip of 1 cm springs along x over a 1 cm cube (x from 0.015 to 0.025, top at z = 0.005).
Model strip_over_cube(const std::vector<Eigen::Vector3d>& x) {
  Fabric strip({0.04, 0.005, 4, 1});
  std::vector<RigidBody> bodies;
  bodies.emplace_back("cube", test::cube(Eigen::Vector3d(0.015, -0.0025, -0.005), 0.01));
  return Model{strip, test::linear_table(100.0), test::linear_table(100.0), std::vector<AxisMask>(x.size(), 0),
               std::move(bodies), x};
}

TEST(EdgeContact, TheTermsForcesAreItsEnergysDerivativeAndPushOut) {
  Fabric strip({0.04, 0.005, 4, 1});
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < strip.node_count(); ++k) {
    Eigen::Vector3d p = strip.rest_position(k);
    p.z() = strip.i_of(k) == 2 ? 0.005 : 0.0042;  // on the top; either side of the cube, 0.8 mm below it
    x.push_back(p + Eigen::Vector3d(0.0, 0.0001 * k, 0.0));
  }
  Model model = strip_over_cube(x);
  const EdgeContact term(model, {45.0}, 1e5);
  EXPECT_EQ(term.edge_count(), 12);  // the cube's; its faces' diagonals turn by nothing
  ASSERT_GT(term.energy(model, x), 0.0);
  const double h = 1e-9;
  for (int node = 0; node < model.node_count(); ++node) {
    const Eigen::Vector3d force = term.force_at(model, x, node, x[static_cast<std::size_t>(node)]);
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<Eigen::Vector3d> plus = x, minus = x;
      plus[static_cast<std::size_t>(node)][axis] += h;
      minus[static_cast<std::size_t>(node)][axis] -= h;
      const double derivative = (term.energy(model, plus) - term.energy(model, minus)) / (2 * h);
      EXPECT_NEAR(force[axis], -derivative, 1e-6 * force.norm() + 1e-9) << node << " " << axis;
      EXPECT_NEAR(term.node_energy_change(model, x, node, plus[static_cast<std::size_t>(node)]),
                  term.energy(model, plus) - term.energy(model, x), 1e-15);
    }
    // The springs under the edges are pushed up, out of the cube; the nodes at the strip's ends
    // carry no spring that reaches under one.
    const int i = model.fabric.i_of(node);
    if (i == 0 || i == 4) EXPECT_EQ(force.norm(), 0.0) << node;
    else EXPECT_GT(force.z(), 0.0) << node;
  }
}

TEST(EdgeContact, OnlyNewtonCarriesIt) {
  const Model model = strip_over_cube(std::vector<Eigen::Vector3d>(10, Eigen::Vector3d::Zero()));
  const EdgeContact term(model, {45.0}, 1e5);
  EXPECT_EQ(term.needs(), SolverNeeds(SolverNeed::stiff_penalty));
  EXPECT_THROW(EdgeContact(model, {45.0}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::edge_contact_test
