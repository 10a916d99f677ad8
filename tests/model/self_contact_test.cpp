// Fabric–fabric contact (model/self_contact.hpp): the pairs it finds against a brute force over
// every node and triangle; the penalty's force against central differences of its energy on a
// strip folded onto itself; Newton's Gauss–Newton block against differences of the force where
// it is exact (a node over a triangle's inside, whose distance is linear in the node); and the
// neighbourhood and sewn nodes it leaves alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include "fabform/geometry/closest_point.hpp"
#include "fabform/model/seam.hpp"
#include "fabform/model/self_contact.hpp"
#include "support/flat_models.hpp"
#include "support/term_checks.hpp"

namespace fabform::self_contact_test {
namespace {

constexpr double kThickness = 1e-3;

Fabric strip(int along, int across) {
  FabricSpec spec;
  spec.width_m = 0.01 * along, spec.height_m = 0.01 * across;
  spec.divisions_warp = along, spec.divisions_weft = across;
  return Fabric(spec);
}

std::vector<int> unsewn(int nodes) {
  std::vector<int> self(static_cast<std::size_t>(nodes));
  for (int k = 0; k < nodes; ++k) self[static_cast<std::size_t>(k)] = k;
  return self;
}

// A 1 cm strip of 6 × 2 cells folded at its middle column: the far half laid back over the near
// half `gap` above it, each node moved at random by up to a fifth of the gap.
Positions folded(const Fabric& f, double gap, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jiggle(-0.2 * gap, 0.2 * gap);
  const double fold = 0.01 * (f.nodes_warp() - 1) / 2;
  Positions x;
  for (int k = 0; k < f.node_count(); ++k) {
    Eigen::Vector3d p = f.rest_position(k);
    if (p.x() > fold) p.x() = 2.0 * fold - p.x(), p.z() = gap;
    x.push_back(p + Eigen::Vector3d(jiggle(random), jiggle(random), jiggle(random)));
  }
  return x;
}

TEST(SelfContact, FindsThePairsABruteForceFinds) {
  const Fabric f = strip(6, 2);
  const SelfContact contact(f, unsewn(f.node_count()), kThickness, 1e3);
  for (const double gap : {0.2e-3, 0.7e-3, 1.5e-3}) {
    const Positions x = folded(f, gap, 3);
    std::vector<std::pair<int, int>> expected;
    for (int node = 0; node < f.node_count(); ++node)
      for (std::size_t t = 0; t < contact.triangles().size(); ++t) {
        const auto& tri = contact.triangles()[t];
        // The neighbourhood left alone: triangles touching the node's own faces.
        bool near = false;
        for (const int corner : tri)
          for (const int face : f.faces_at(node))
            for (int c = 0; c < f.faces()[static_cast<std::size_t>(face)].corners; ++c)
              near = near || f.faces()[static_cast<std::size_t>(face)].corner[static_cast<std::size_t>(c)] == corner;
        if (near) continue;
        const auto at = [&](int n) { return x[static_cast<std::size_t>(n)]; };
        const Eigen::Vector3d q = closest_point_on_triangle(at(node), at(tri[0]), at(tri[1]), at(tri[2])).point;
        if ((at(node) - q).norm() < kThickness) expected.emplace_back(node, static_cast<int>(t));
      }
    std::vector<std::pair<int, int>> found;
    for (const ProximityPair& p : contact.pairs(x)) {
      found.emplace_back(p.node, p.triangle);
      const auto& tri = contact.triangles()[static_cast<std::size_t>(p.triangle)];
      const Eigen::Vector3d q = p.weights[0] * x[static_cast<std::size_t>(tri[0])] +
                                p.weights[1] * x[static_cast<std::size_t>(tri[1])] +
                                p.weights[2] * x[static_cast<std::size_t>(tri[2])];
      EXPECT_NEAR((x[static_cast<std::size_t>(p.node)] - q).norm(), p.distance_m, 1e-15);
      EXPECT_LT((x[static_cast<std::size_t>(p.node)] - q - p.distance_m * p.direction).norm(), 1e-15);
    }
    EXPECT_EQ(found, expected) << "gap " << gap;
    if (gap < kThickness) {
      EXPECT_FALSE(found.empty());
    } else if (gap > kThickness * 1.4) {
      EXPECT_TRUE(found.empty());
    }
  }
}

TEST(SelfContact, ForceIsMinusTheGradientOfItsEnergy) {
  const Fabric f = strip(6, 2);
  const Model model = test::free_model(f);
  const SelfContact contact(f, unsewn(f.node_count()), kThickness, 1e3);
  for (const unsigned seed : {1u, 2u, 3u}) {
    const Positions x = folded(f, 0.5e-3, seed);
    test::expect_force_is_minus_the_gradient(model, contact, x, 1e-9, 1e-5);
    // The one-pass forces are what each node's own gives.
    std::vector<Eigen::Vector3d> all(x.size(), Eigen::Vector3d::Zero());
    contact.add_forces(model, x, all);
    for (int k = 0; k < f.node_count(); ++k)
      EXPECT_LT((all[static_cast<std::size_t>(k)] - contact.force_at(model, x, k, x[static_cast<std::size_t>(k)])).norm(), 1e-15);
  }
}

// One node of the upper ply lowered to half the thickness over the inside of a lower triangle,
// the rest of that ply three thicknesses up: one pair, whose distance is linear in the node, so
// the node's block of the exact Hessian is ψ'' n nᵀ, which Newton's block must be.
TEST(SelfContact, NewtonsBlockIsTheForceDerivativeWhereTheDistanceIsLinear) {
  const Fabric f = strip(6, 2);
  const Model model = test::free_model(f);
  const SelfContact contact(f, unsewn(f.node_count()), kThickness, 1e3);
  Positions x = folded(f, 3.0 * kThickness, 5);
  const int node = f.node(5, 1);
  x[static_cast<std::size_t>(node)] = Eigen::Vector3d(0.01667, 0.00333, 0.5 * kThickness);
  const std::vector<ProximityPair> pairs = contact.pairs(x);
  ASSERT_EQ(pairs.size(), 1u);
  ASSERT_EQ(pairs[0].node, node);
  EXPECT_GT(*std::min_element(pairs[0].weights.begin(), pairs[0].weights.end()), 0.2);
  const Eigen::MatrixXd k = test::dense_stiffness(model, contact, x);
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues().minCoeff(), -1e-9 * k.cwiseAbs().maxCoeff());
  const double h = 1e-9;
  for (int axis = 0; axis < 3; ++axis) {
    Positions plus = x, minus = x;
    plus[static_cast<std::size_t>(node)][axis] += h, minus[static_cast<std::size_t>(node)][axis] -= h;
    const Eigen::Vector3d derivative = (contact.force_at(model, plus, node, plus[static_cast<std::size_t>(node)]) -
                                        contact.force_at(model, minus, node, minus[static_cast<std::size_t>(node)])) /
                                       (2.0 * h);
    EXPECT_LT((k.block<3, 1>(3 * node, 3 * node + axis) + derivative).norm(), 1e-6 * k.cwiseAbs().maxCoeff()) << axis;
  }
}

TEST(SelfContact, LeavesAFlatFabricAndItsSewnNodesAlone) {
  const Fabric f = strip(6, 2);
  const SelfContact flat(f, unsewn(f.node_count()), kThickness, 1e3);
  EXPECT_FALSE(flat.pairs(test::flat_positions(f), 0.02).empty());  // its far cells are within 2 cm
  EXPECT_TRUE(flat.pairs(test::flat_positions(f)).empty());
  // A tube of the strip: its first and last columns sewn and laid on one another.
  Model model = test::free_model(f);
  std::vector<int> left, right;
  for (int j = 0; j < f.nodes_weft(); ++j) left.push_back(f.node(0, j)), right.push_back(f.node(6, j));
  model.terms.push_back(std::make_shared<SeamTerm>(std::vector<Seam>{{"tube", stitches_by_arc_length(f, left, right), 0.02}},
                                                   1e5, f.node_count()));
  Positions ring;
  for (int k = 0; k < f.node_count(); ++k) {
    const double angle = 2.0 * M_PI * f.i_of(k) / 6.0;
    ring.emplace_back(0.01 * std::cos(angle), 0.01 * std::sin(angle), 0.01 * f.j_of(k));
  }
  const SelfContact tube(f, sewn_representatives(model), kThickness, 1e3);
  EXPECT_TRUE(tube.pairs(ring).empty());
  EXPECT_FALSE(SelfContact(f, unsewn(f.node_count()), kThickness, 1e3).pairs(ring).empty());
  EXPECT_EQ(tube.needs(), SolverNeeds(SolverNeed::stiff_penalty));
  EXPECT_THROW(SelfContact(f, unsewn(f.node_count()), -1e-3, 1e3), std::invalid_argument);
}

// A broken state (the solvers report its NaN) has no pairs rather than cubes at NaN.
TEST(SelfContact, ABrokenStateHasNoPairs) {
  const Fabric f = strip(6, 2);
  const SelfContact contact(f, unsewn(f.node_count()), kThickness, 1e3);
  Positions x = folded(f, 0.5e-3, 1);
  ASSERT_FALSE(contact.pairs(x).empty());
  x[3].y() = std::nan("");
  EXPECT_TRUE(contact.pairs(x).empty());
}

}  // namespace
}  // namespace fabform::self_contact_test
