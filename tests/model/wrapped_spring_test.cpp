// A spring wrapped over an edge (wrapped_spring.hpp, spring_path.hpp): its force is minus the
// gradient of its energy and its Hessian minus the derivative of its force, by central
// differences, with the wrap point found anew at every perturbed position (so the envelope
// theorem and the Schur complement are what is checked); the projected Hessian is positive
// semi-definite; and the spring term of a strip over a cube's edge passes every term check.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "fabform/model/spring_path.hpp"
#include "fabform/model/spring_term.hpp"
#include "fabform/model/wrapped_spring.hpp"
#include "support/clamped_fabric.hpp"
#include "support/shapes.hpp"
#include "support/term_checks.hpp"

namespace fabform::wrapped_spring_test {
namespace {

using V = Eigen::Vector3d;

// A box's edge along y at x = z = 0 (the body x < 0, z < 0), from y = 0 to y = 1.
const SharpEdge kEdge{V(0.0, 0.0, 0.0), V(0.0, 1.0, 0.0), V::UnitZ(), V::UnitX()};

// A table steeper past 5 % strain, so T, T' > 0 where checked and T' changes along the way.
TensionTable knit() { return TensionTable({{0.0, 0.0}, {0.05, 10.0}, {1.0, 400.0}}, "knit"); }

Spring spring_of(double rest_length) { return Spring{0, 1, rest_length, 0.01, SpringKind::warp}; }

double energy(const V& a, const V& b, const Spring& s) {
  const auto wrap = wrap_over(kEdge, a, b, 0.0);
  EXPECT_TRUE(wrap);
  return wrapped_spring_energy(*wrap, s, knit());
}

Vector6d forces(const Vector6d& x, const Spring& s) {
  const V a = x.head<3>(), b = x.tail<3>();
  const auto wrap = wrap_over(kEdge, a, b, 0.0);
  EXPECT_TRUE(wrap);
  Vector6d f;
  f << wrapped_spring_force(a, *wrap, s, knit()), wrapped_spring_force(b, *wrap, s, knit());
  return f;
}

class WrappedSpringAt : public ::testing::TestWithParam<std::pair<V, V>> {};

TEST_P(WrappedSpringAt, ForceAndHessianAgreeWithTheEnergyByCentralDifferences) {
  const auto [a, b] = GetParam();
  const Spring s = spring_of(0.9 * (b - a).norm());
  Vector6d x;
  x << a, b;
  const Vector6d f = forces(x, s);
  const auto wrap = wrap_over(kEdge, a, b, 0.0);
  ASSERT_TRUE(wrap);
  const Matrix6d hessian = wrapped_spring_hessian(a, b, *wrap, s, knit(), false);
  const double h = 1e-7;
  for (int i = 0; i < 6; ++i) {
    Vector6d plus = x, minus = x;
    plus[i] += h, minus[i] -= h;
    const double slope = (energy(plus.head<3>(), plus.tail<3>(), s) - energy(minus.head<3>(), minus.tail<3>(), s)) / (2 * h);
    EXPECT_NEAR(-slope, f[i], 1e-6 * f.cwiseAbs().maxCoeff()) << i;
    const Vector6d column = -(forces(plus, s) - forces(minus, s)) / (2 * h);
    EXPECT_LT((column - hessian.col(i)).cwiseAbs().maxCoeff(), 1e-5 * hessian.cwiseAbs().maxCoeff()) << i;
  }
  const Eigen::SelfAdjointEigenSolver<Matrix6d> projected(wrapped_spring_hessian(a, b, *wrap, s, knit(), true));
  EXPECT_GE(projected.eigenvalues().minCoeff(), -1e-9 * projected.eigenvalues().cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(
    WrappedSpring, WrappedSpringAt,
    ::testing::Values(std::pair<V, V>{V(-0.3, 0.4, 0.05), V(0.04, 0.55, -0.35)},   // across, obliquely
                      std::pair<V, V>{V(-0.02, 0.5, 0.0), V(0.0, 0.5, -0.03)},      // a short spring, square
                      std::pair<V, V>{V(-0.24, 0.61, 0.01), V(0.04, 1.95, -0.44)}));  // held at the edge's end

// Whatever the wrap, the two legs pull their nodes towards the edge with one tension.
TEST(WrappedSpring, BothLegsCarryTheSameTensionTowardsTheEdge) {
  const V a(-0.3, 0.4, 0.05), b(0.04, 0.55, -0.35);
  const auto wrap = wrap_over(kEdge, a, b, 0.0);
  ASSERT_TRUE(wrap);
  const Spring s = spring_of(0.5);
  const V fa = wrapped_spring_force(a, *wrap, s, knit()), fb = wrapped_spring_force(b, *wrap, s, knit());
  EXPECT_NEAR(fa.norm(), fb.norm(), 1e-12 * fa.norm());
  EXPECT_NEAR(fa.normalized().dot((wrap->point - a).normalized()), 1.0, 1e-14);
  EXPECT_NEAR(fa.norm(), s.width * knit().tension(wrap->length / s.rest_length - 1.0), 1e-12);
  // The edge takes −(fa + fb); along the edge it takes nothing (p slides to where they balance).
  EXPECT_NEAR((fa + fb).dot(wrap->axis), 0.0, 1e-12 * fa.norm());
}

// A strip of 4 warp springs, 1 cm each, over the top edge x = 0.025 of the cube [0.015, 0.025]
// (x) at z = 0.005: nodes 0–2 above the top's level, 3–4 beside its side face, so the spring
// from 2 to 3 wraps.
Model strip_over_cube() {
  Fabric strip({0.04, 0.005, 4, 1});
  std::vector<V> start;
  for (int k = 0; k < strip.node_count(); ++k) {
    // Stretched 3 % across and along, off the table's kinks at 0 and 5 % strain.
    V p = 1.03 * strip.rest_position(k) + V(0.0, 0.0, 0.0055);
    if (strip.i_of(k) >= 3) p = V(0.027 + 0.004 * (strip.i_of(k) - 3), p.y(), 0.003 - 0.004 * (strip.i_of(k) - 3));
    if (strip.i_of(k) == 2) p.x() = 0.0135;
    start.push_back(p);
  }
  std::vector<RigidBody> bodies;
  bodies.emplace_back("cube", test::cube(V(0.015, -0.0025, -0.005), 0.01));
  bodies.back().wrap_edges_sharper_than(45.0);
  return Model{strip, knit(), knit(), std::vector<AxisMask>(start.size(), 0), std::move(bodies), start};
}

TEST(WrappedSpring, TheStretchTermOverAnEdgePassesEveryTermCheck) {
  const Model model = strip_over_cube();
  int wrapped = 0;
  for (const Spring& s : model.fabric.springs())
    wrapped += spring_wrap(model, s, model.start[static_cast<std::size_t>(s.a)], model.start[static_cast<std::size_t>(s.b)]) ? 1 : 0;
  ASSERT_EQ(wrapped, 2) << "one warp spring over the edge in each of the strip's two rows";
  const SpringTerm& term = static_cast<const SpringTerm&>(*model.terms.front());
  test::expect_force_is_minus_the_gradient(model, term, model.start, 1e-8, 1e-6);
  test::expect_node_changes_are_the_whole(model, term, model.start,
                                          {model.fabric.node(2, 0), model.fabric.node(3, 1)}, V(1e-5, 2e-6, -3e-6));
  test::expect_stiffness_is_minus_the_force_derivative(model, term, model.start, 1e-8, 1e-5);
}

}  // namespace
}  // namespace fabform::wrapped_spring_test
