// A strip held at both ends over a box's edge, frictionless, against the taut string's closed
// form: wrapped over the edge, every warp spring carries one tension, so each is stretched to
// the length of the path end → edge → end over their number, and the nodes lie on its two
// legs. Node-only contact (seed 003) cannot hold it so: there a spring cuts the corner.
#include <gtest/gtest.h>

#include <string>

#include "fabform/model/spring_cuts.hpp"
#include "fabform/model/spring_path.hpp"
#include "fabform/solver/solve.hpp"
#include "support/clamped_fabric.hpp"
#include "support/shapes.hpp"

namespace fabform::strip_over_edge_test {
namespace {

using V = Eigen::Vector3d;

// The box [-0.04, 0]³ shifted to y ∈ [-0.02, 0.02]: its top edge runs along y at x = z = 0.
// The strip, 4 cm by 4 mm in 8 × 1 cells, is held at x = −2 cm, 2 mm above the top, and at
// x = 4 mm beside the side face, 3 cm down.
const V kHeldA(-0.02, 0.0, 0.002), kHeldB(0.004, 0.0, -0.03);
constexpr double kLength = 0.04;

double path_length() { return kHeldA.norm() + kHeldB.norm(); }  // over the edge point (0, y, 0)

Model strip_over_edge(bool wrap) {
  Fabric strip({kLength, 0.004, 8, 1});
  std::vector<AxisMask> locks(static_cast<std::size_t>(strip.node_count()), 0);
  std::vector<V> start;
  // Laid out clear of the box, over a point 1 mm out from the edge, evenly by length.
  const V over(0.001, 0.0, 0.001);
  const double first = (over - kHeldA).norm(), total = first + (kHeldB - over).norm();
  for (int k = 0; k < strip.node_count(); ++k) {
    const double along = total * strip.i_of(k) / 8.0;
    V p = along <= first ? V(kHeldA + (over - kHeldA) * (along / first))
                         : V(over + (kHeldB - over) * ((along - first) / (total - first)));
    p.y() = strip.rest_position(k).y();
    start.push_back(p);
    if (strip.i_of(k) == 0 || strip.i_of(k) == 8) locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
  }
  std::vector<RigidBody> bodies;
  bodies.emplace_back("box", test::cube(V(-0.04, -0.02, -0.04), 0.04));
  if (wrap) bodies.back().wrap_edges_sharper_than(45.0);
  return Model{strip, test::linear_table(100.0), test::linear_table(100.0), locks, std::move(bodies), start};
}

SolverState solved(const Model& model, const std::string& solver) {
  SolverSpec spec;
  spec.name = solver;
  spec.set_tolerance_N(1e-10);
  spec.relax.max_iterations = 200000;
  SolverState state = SolverState::at_start(model);
  const Summary summary = solve(model, state, spec);
  EXPECT_TRUE(summary.converged()) << solver << ": " << summary.message;
  return state;
}

class StripOverEdge : public ::testing::TestWithParam<std::string> {};

TEST_P(StripOverEdge, WrapsItAsATautString) {
  const Model model = strip_over_edge(true);
  const SolverState state = solved(model, GetParam());
  const double strain = path_length() / kLength - 1.0;  // 25.9 %
  int wrapped = 0;
  for (const Spring& s : model.fabric.springs()) {
    if (s.kind != SpringKind::warp) continue;
    const V &a = state.x[static_cast<std::size_t>(s.a)], &b = state.x[static_cast<std::size_t>(s.b)];
    // e = 1e-10 N on springs of stiffness w·k/L = 0.4 / 0.005 = 80 N/m leaves ~1e-12 m.
    EXPECT_NEAR(spring_path_strain(model, s, a, b), strain, 1e-8) << s.a << "-" << s.b;
    if (const auto wrap = spring_wrap(model, s, a, b)) {
      ++wrapped;
      EXPECT_NEAR(wrap->point.x(), 0.0, 1e-12);
      EXPECT_NEAR(wrap->point.z(), 0.0, 1e-12);
    }
  }
  EXPECT_EQ(wrapped, 2) << "one spring in each row runs over the edge";
  // Every node on a leg: the line from its held end to the edge point (0, y, 0).
  for (int k = 0; k < model.node_count(); ++k) {
    const V& p = state.x[static_cast<std::size_t>(k)];
    const V end = p.x() < 0.0 ? kHeldA : kHeldB;
    const V along = V(end.x(), 0.0, end.z()).normalized();
    const V off = V(p.x(), 0.0, p.z()) - along.dot(V(p.x(), 0.0, p.z())) * along;
    EXPECT_LT(off.norm(), 1e-9) << "node " << k;
    EXPECT_NEAR(p.y(), model.start[static_cast<std::size_t>(k)].y(), 1e-9) << "node " << k;
  }
  EXPECT_EQ(find_spring_cuts(model, state.x).springs, 0);
}

INSTANTIATE_TEST_SUITE_P(Solvers, StripOverEdge, ::testing::Values("newton", "relax"),
                         [](const auto& case_info) { return case_info.param; });

TEST(StripOverEdge, WithContactAtTheNodesAloneASpringCutsTheCorner) {
  const Model model = strip_over_edge(false);
  const SolverState state = solved(model, "newton");
  const SpringCuts cuts = find_spring_cuts(model, state.x);
  EXPECT_EQ(cuts.springs, 2);
  EXPECT_GT(cuts.deepest_m, 1e-4);
}

TEST(StripOverEdge, DynamicRefusesAWrappedSpring) {
  const Model model = strip_over_edge(true);
  SolverSpec spec;
  spec.name = "dynamic";
  SolverState state = SolverState::at_start(model);
  EXPECT_THROW(solve(model, state, spec), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::strip_over_edge_test
