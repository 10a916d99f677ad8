// Seams (model/seam.hpp): stitches matched by arc length against the flat pattern's own
// polylines walked point by point; the term checked as every term is, by central differences
// (a seam of equal edges, one of unequal edges, and a dart whose two edges share their point);
// its figures against a gap set by hand; and nodes sewn together found as one point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include "fabform/model/seam.hpp"
#include "support/flat_models.hpp"
#include "support/term_checks.hpp"

namespace fabform::seam_test {
namespace {

Fabric rectangle(double width, double height, int along_x, int along_y) {
  FabricSpec spec;
  spec.width_m = width, spec.height_m = height;
  spec.divisions_warp = along_x, spec.divisions_weft = along_y;
  return Fabric(spec);
}

std::vector<int> column(const Fabric& f, int i) {
  std::vector<int> nodes;
  for (int j = 0; j < f.nodes_weft(); ++j) nodes.push_back(f.node(i, j));
  return nodes;
}

std::vector<int> row(const Fabric& f, int j) {
  std::vector<int> nodes;
  for (int i = 0; i < f.nodes_warp(); ++i) nodes.push_back(f.node(i, j));
  return nodes;
}

// The point at fraction s of a chain's flat length, walked in many small steps.
Eigen::Vector3d walked_point(const Fabric& f, const std::vector<int>& chain, double s) {
  double total = 0.0;
  for (std::size_t k = 1; k < chain.size(); ++k)
    total += (f.rest_position(chain[k]) - f.rest_position(chain[k - 1])).norm();
  double left = s * total;
  for (std::size_t k = 1; k < chain.size(); ++k) {
    const Eigen::Vector3d a = f.rest_position(chain[k - 1]), b = f.rest_position(chain[k]);
    const double length = (b - a).norm();
    if (left <= length) return a + (left / length) * (b - a);
    left -= length;
  }
  return f.rest_position(chain.back());
}

double fraction_of(const Fabric& f, const std::vector<int>& chain, int node) {
  double before = 0.0, total = 0.0;
  for (std::size_t k = 1; k < chain.size(); ++k) {
    const double length = (f.rest_position(chain[k]) - f.rest_position(chain[k - 1])).norm();
    total += length;
    if (static_cast<int>(k) <= static_cast<int>(std::find(chain.begin(), chain.end(), node) - chain.begin()))
      before += length;
  }
  return before / total;
}

Eigen::Vector3d stitch_point(const Fabric& f, const Stitch& s) {
  return (1.0 - s.t) * f.rest_position(s.first) + s.t * f.rest_position(s.second);
}

TEST(Seam, EqualEdgesAreSewnNodeForNode) {
  const Fabric f = rectangle(0.3, 0.1, 6, 4);
  const std::vector<int> left = column(f, 0), right = column(f, 6);
  const std::vector<Stitch> stitches = stitches_by_arc_length(f, left, right);
  ASSERT_EQ(stitches.size(), 10u);
  double length = 0.0;
  for (const Stitch& s : stitches) {
    EXPECT_TRUE(s.t == 0.0 || s.t == 1.0) << s.t;
    const int partner = s.t == 0.0 ? s.first : s.second;
    EXPECT_EQ(f.j_of(partner), f.j_of(s.node));
    EXPECT_NE(f.i_of(partner), f.i_of(s.node));
    length += s.length_m;
  }
  // Each edge's nodes stand for half their share of it: the two halves make the seam's length.
  EXPECT_NEAR(length, 0.1, 1e-15);
}

TEST(Seam, UnequalEdgesAreMatchedByArcLength) {
  const Fabric f = rectangle(0.4, 0.1, 8, 3);
  const std::vector<int> bottom = row(f, 0), left = column(f, 0);  // 9 nodes against 4, 0.4 m against 0.1 m
  const std::vector<Stitch> stitches = stitches_by_arc_length(f, bottom, left);
  ASSERT_EQ(stitches.size(), 13u);
  double length = 0.0;
  for (std::size_t k = 0; k < stitches.size(); ++k) {
    const Stitch& s = stitches[k];
    const bool from_bottom = k < bottom.size();  // the first edge's nodes come first
    const std::vector<int>& own = from_bottom ? bottom : left;
    const std::vector<int>& other = from_bottom ? left : bottom;
    const Eigen::Vector3d expected = walked_point(f, other, fraction_of(f, own, s.node));
    EXPECT_LT((stitch_point(f, s) - expected).norm(), 1e-12) << "node " << s.node;
    length += s.length_m;
  }
  EXPECT_NEAR(length, 0.5 * (0.4 + 0.1), 1e-15);
}

TEST(Seam, AChainOfOneNodeIsRefused) {
  const Fabric f = rectangle(0.1, 0.1, 2, 2);
  EXPECT_THROW(stitches_by_arc_length(f, {0}, column(f, 2)), std::invalid_argument);
  EXPECT_THROW(stitches_by_arc_length(f, {0, 0}, column(f, 2)), std::invalid_argument);
}

// A 4 × 3 fabric crumpled at random, with three seams: its left edge on its right (equal), its
// bottom on its top reversed over part of it (unequal), and a dart (the left edge's lower half on
// the bottom edge's left part, both from the corner they share).
struct Crumpled {
  Model model;
  SeamTerm seams;
};

Crumpled crumpled() {
  const Fabric f = rectangle(0.2, 0.15, 4, 3);
  Model model = test::free_model(f);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jiggle(-0.01, 0.01);
  for (int k = 0; k < f.node_count(); ++k)
    model.start.push_back(f.rest_position(k) + Eigen::Vector3d(jiggle(random), jiggle(random), 3.0 * jiggle(random)));
  std::vector<int> top_part = {f.node(3, 3), f.node(2, 3), f.node(1, 3)};
  std::vector<Seam> seams = {
      {"sides", stitches_by_arc_length(f, column(f, 0), column(f, 4)), 0.15},
      {"hem", stitches_by_arc_length(f, row(f, 0), top_part), 0.2},
      {"dart", stitches_by_arc_length(f, {f.node(0, 0), f.node(0, 1)}, {f.node(0, 0), f.node(1, 0), f.node(2, 0)}), 0.05}};
  return {std::move(model), SeamTerm(std::move(seams), 3.0e5, f.node_count())};
}

TEST(SeamTerm, ForceIsMinusTheGradientOfItsEnergy) {
  const Crumpled c = crumpled();
  test::expect_force_is_minus_the_gradient(c.model, c.seams, c.model.start, 1e-7, 1e-6);
  test::expect_node_changes_are_the_whole(c.model, c.seams, c.model.start, {0, 4, 5, 17, 19}, Eigen::Vector3d(1e-4, -2e-4, 3e-4));
}

TEST(SeamTerm, StiffnessIsMinusTheDerivativeOfItsForce) {
  const Crumpled c = crumpled();
  test::expect_stiffness_is_minus_the_force_derivative(c.model, c.seams, c.model.start, 1e-7, 1e-6);
  // A quadratic energy: its Hessian is the same wherever the nodes are, and positive semi-definite.
  const Eigen::MatrixXd k = test::dense_stiffness(c.model, c.seams, c.model.start);
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues().minCoeff(), -1e-9 * k.cwiseAbs().maxCoeff());
}

TEST(SeamTerm, FiguresReadTheGapAndTheForcePerLength) {
  const Fabric f = rectangle(0.3, 0.1, 6, 4);
  const Model model = test::free_model(f);
  const double stiffness = 2.0e5, open = 1e-4;
  const SeamTerm term({{"tube", stitches_by_arc_length(f, column(f, 0), column(f, 6)), 0.1}}, stiffness, f.node_count());
  Positions x = test::flat_positions(f);
  // The right edge laid on the left, 0.1 mm above it along z.
  for (int j = 0; j < f.nodes_weft(); ++j)
    x[static_cast<std::size_t>(f.node(6, j))] = x[static_cast<std::size_t>(f.node(0, j))] + Eigen::Vector3d(0, 0, open);
  const std::vector<SeamFigures> figures = term.figures(x);
  ASSERT_EQ(figures.size(), 1u);
  EXPECT_EQ(figures[0].name, "tube");
  EXPECT_NEAR(figures[0].gap_max_m, open, 1e-15);
  EXPECT_NEAR(figures[0].tension_mean_N_m, stiffness * open, 1e-9);
  EXPECT_NEAR(figures[0].tension_max_N_m, stiffness * open, 1e-9);
  // The force on an edge's middle node: the tension times the length of seam it stands for.
  const int middle = f.node(6, 2);
  EXPECT_NEAR(term.force_at(model, x, middle, x[static_cast<std::size_t>(middle)]).z(), -stiffness * open * 0.025, 1e-12);
}

TEST(SeamTerm, OnlyNewtonTakesIt) {
  const Crumpled c = crumpled();
  EXPECT_EQ(c.seams.needs(), SolverNeeds(SolverNeed::stiff_penalty));
  EXPECT_THROW(SeamTerm({}, 0.0, 4), std::invalid_argument);
}

TEST(SeamTerm, NodesSewnNodeForNodeAreOnePoint) {
  const Fabric f = rectangle(0.3, 0.1, 6, 4);
  Model model = test::free_model(f);
  model.terms.push_back(std::make_shared<SeamTerm>(
      std::vector<Seam>{{"tube", stitches_by_arc_length(f, column(f, 0), column(f, 6)), 0.1}}, 1e5, f.node_count()));
  const std::vector<int> sewn = sewn_representatives(model);
  for (int j = 0; j < f.nodes_weft(); ++j) {
    EXPECT_EQ(sewn[static_cast<std::size_t>(f.node(6, j))], f.node(0, j));
    EXPECT_EQ(sewn[static_cast<std::size_t>(f.node(0, j))], f.node(0, j));
    EXPECT_EQ(sewn[static_cast<std::size_t>(f.node(3, j))], f.node(3, j));
  }
}

}  // namespace
}  // namespace fabform::seam_test
