// Spring contact (spring_contact.hpp): the depths of a spring's sample points against the depth of
// a point in a cube worked out by hand (its distance to the nearest face), the term's forces and
// stiffness against central differences of its energy and forces, its energy continuous as a
// node slides past a faceted cylinder's narrow facets (where the edge penalty's jumps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fabform/model/model.hpp"
#include "fabform/model/spring_contact.hpp"
#include "fabform/model/spring_cuts.hpp"
#include "fabform/solver/solve.hpp"
#include "support/clamped_fabric.hpp"
#include "support/scene_models.hpp"
#include "support/shapes.hpp"
#include "support/term_checks.hpp"
#include "test_paths.hpp"

namespace fabform::spring_contact_test {
namespace {

// A 1 cm cube from (0.015, −0.0025, −0.005): its top at z = 0.005, its sides at x = 0.015, 0.025.
constexpr double kStiffness = 1e5;
Model strip_over_cube(std::vector<Eigen::Vector3d> x) {
  Fabric strip({0.04, 0.005, 4, 1});
  std::vector<RigidBody> bodies;
  bodies.emplace_back("cube", test::cube(Eigen::Vector3d(0.015, -0.0025, -0.005), 0.01));
  return Model{strip, test::linear_table(100.0), test::linear_table(100.0), std::vector<AxisMask>(x.size(), 0),
               std::move(bodies), x};
}

// The strip's middle node on the cube's top, its neighbours either side of it, 0.8 mm under the
// top: the springs to them cut the cube's two upper edges.
std::vector<Eigen::Vector3d> strip_cutting_edges() {
  Fabric strip({0.04, 0.005, 4, 1});
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < strip.node_count(); ++k) {
    Eigen::Vector3d p = strip.rest_position(k);
    p.z() = strip.i_of(k) == 2 ? 0.005 : 0.0042;
    x.push_back(p + Eigen::Vector3d(0.0, 0.0001 * k, 0.0));
  }
  return x;
}

// How deep p lies in the cube: its distance to the nearest face, 0 outside.
double cube_depth(const Eigen::Vector3d& p) {
  const Eigen::Vector3d lo(0.015, -0.0025, -0.005), hi(0.025, 0.0075, 0.005);
  const double depth = std::min((p - lo).minCoeff(), (hi - p).minCoeff());
  return std::max(depth, 0.0);
}

// φ of spring_contact.hpp, written out again: onset h = 2 % of the strip's mean warp and weft
// spring, eight of 1 cm and five of 5 mm.
double phi(double depth) {
  const double h = 0.02 * (8 * 0.01 + 5 * 0.005) / 13, k = kStiffness;
  return depth < h ? k * depth * depth * depth / (6.0 * h) : k * (0.5 * depth * depth - 0.5 * h * depth + h * h / 6.0);
}

TEST(SpringContact, ItsEnergyIsThePenaltyOfTheSamplesDepthsInTheCube) {
  const std::vector<Eigen::Vector3d> x = strip_cutting_edges();
  const Model model = strip_over_cube(x);
  const SpringContact term(model, {0}, kStiffness);
  double expected = 0.0;
  for (const Spring& s : model.fabric.springs()) {
    if (s.kind == SpringKind::bend) continue;
    for (int i = 0; i < SpringContact::kSamples; ++i) {
      const double t = (i + 0.5) / SpringContact::kSamples;
      expected += phi(cube_depth(x[static_cast<std::size_t>(s.a)] + t * (x[static_cast<std::size_t>(s.b)] -
                                                                          x[static_cast<std::size_t>(s.a)]))) /
                  SpringContact::kSamples;
    }
  }
  ASSERT_GT(expected, 0.0);
  EXPECT_NEAR(term.energy(model, x), expected, 1e-12 * expected);
}

TEST(SpringContact, ItsForcesAreItsEnergysDerivativeAndPushOut) {
  const std::vector<Eigen::Vector3d> x = strip_cutting_edges();
  const Model model = strip_over_cube(x);
  const SpringContact term(model, {0}, kStiffness);
  // Steps of 1e-9 m against depths of 1e-4 m: the energy is smooth there but where a sample lies on
  // the bisector under an edge, which none of these does.
  test::expect_force_is_minus_the_gradient(model, term, x, 1e-9, 1e-6);
  test::expect_node_changes_are_the_whole(model, term, x, {1, 2, 7}, Eigen::Vector3d(1e-5, -2e-5, 3e-5));
  for (int node = 0; node < model.node_count(); ++node) {
    const Eigen::Vector3d force = term.force_at(model, x, node, x[static_cast<std::size_t>(node)]);
    const int i = model.fabric.i_of(node);
    if (i == 0 || i == 4) EXPECT_EQ(force.norm(), 0.0) << node;  // its springs stay out of the cube
    else EXPECT_GT(force.z(), 0.0) << node;
  }
  std::vector<Eigen::Vector3d> summed(x.size(), Eigen::Vector3d::Zero());
  term.add_forces(model, x, summed);
  for (int node = 0; node < model.node_count(); ++node) {
    const auto k = static_cast<std::size_t>(node);
    EXPECT_LT((summed[k] - term.force_at(model, x, node, x[k])).norm(), 1e-12 * kStiffness * 1e-3) << node;
  }
}

// Each sample's depth is its distance below one face, linear in the nodes' positions: the
// Gauss–Newton matrix is the exact Hessian.
TEST(SpringContact, ItsStiffnessIsMinusItsForcesDerivative) {
  const std::vector<Eigen::Vector3d> x = strip_cutting_edges();
  const Model model = strip_over_cube(x);
  const SpringContact term(model, {0}, kStiffness);
  test::expect_stiffness_is_minus_the_force_derivative(model, term, x, 1e-9, 1e-5);
}

// A 4 × 4 cm square of 5 mm springs, held round its edge, pressed down by 2 kPa onto a rib 2 mm
// wide whose top lies 2 mm under it, between two columns of nodes. The depth of the springs'
// cuts is measured by find_spring_cuts (32 points and a golden-section search, no penalty's
// samples): with node-only contact the nodes either side sink past the rib and the springs
// between them pass through it; with spring contact newton drapes them over its top, no spring
// reaching 0.1 mm in.
double deepest_cut_over_a_rib(bool spring_contact) {
  const test::TempDir dir;
  // The box x ∈ [21.5, 23.5] mm, y ∈ [−10, 50] mm, z ∈ [−32, −2] mm, its faces turned outward.
  std::string obj;
  for (int k = 0; k < 8; ++k)
    obj += "v " + std::to_string(k & 1 ? 0.0235 : 0.0215) + " " + std::to_string(k & 2 ? 0.05 : -0.01) + " " +
           std::to_string(k & 4 ? -0.002 : -0.032) + "\n";
  obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  dir.write("rib.obj", obj);
  const std::string table = test::source_path("materials/synthetic/linear-500.csv");
  const Scene scene = load_scene(dir.write(
      "scene.toml", "[fabric]\nsize_m = [0.04, 0.04]\ndivisions = [8, 8]\nwarp = \"" + table + "\"\nweft = \"" +
                        table + "\"\n[[body]]\nname = \"rib\"\nmesh = \"rib.obj\"\nunits = \"m\"\nspring_contact = " +
                        (spring_contact ? "true" : "false") +
                        "\n[[constraint]]\nnodes = \"perimeter\"\n[pressure]\npressure_Pa = 2000\n"
                        "[solver]\nname = \"newton\"\ntolerance_N = 1e-6\nmax_iterations = 300\n"));
  const Model model = build_model(scene);
  SolverState state = SolverState::at_start(model);
  const Summary summary = solve(model, state, scene.solver);
  EXPECT_TRUE(summary.converged()) << summary.message;
  return find_spring_cuts(model, state.x).deepest_m;
}

TEST(SpringContact, NewtonDrapesTheSpringsOverARibInsteadOfThroughIt) {
  EXPECT_GT(deepest_cut_over_a_rib(false), 5e-4);
  EXPECT_LT(deepest_cut_over_a_rib(true), 1e-4);
}

// A node slid past a faceted cylinder's side, 0.5 mm clear of it, its spring's other end on the
// cylinder's top: the plane-wedge depth of the edge penalty jumps here, where the node lies under
// the planes of the cylinder's narrow facets though outside it. Each step's change of energy is
// bounded by the largest force along the way times the step, so no jump hides between steps (the
// edge penalty, edge_contact_deg = 2, jumps by 34 times that bound on this sweep).
TEST(SpringContact, ItsEnergyIsContinuousBesideNarrowFacets) {
  Fabric pair({0.004, 0.004, 1, 1});
  std::vector<Eigen::Vector3d> x(static_cast<std::size_t>(pair.node_count()), Eigen::Vector3d(0.0, 0.0, 0.05));
  std::vector<RigidBody> bodies;
  bodies.emplace_back("cylinder", test::cylinder_along_y(0.005, -0.02, 0.02, 48));
  Model model{pair, test::linear_table(100.0), test::linear_table(100.0), std::vector<AxisMask>(x.size(), 0),
              std::move(bodies), x};
  const SpringContact term(model, {0}, kStiffness);
  // Node 0 rests on the cylinder's crown; node 1 slides down beside it, just clear of its side.
  x[0] = Eigen::Vector3d(0.0, 0.0, 0.005);
  const int steps = 4000;
  double largest_force = 0.0, largest_change = 0.0, previous = 0.0;
  const double step_angle = 1.2 / steps;
  for (int k = 0; k <= steps; ++k) {
    const double angle = 0.3 + k * step_angle;  // from the crown's side round towards the equator
    x[1] = Eigen::Vector3d(0.0055 * std::sin(angle), 0.0, 0.0055 * std::cos(angle));
    const double e = term.energy(model, x);
    largest_force = std::max(largest_force, term.force_at(model, x, 1, x[1]).norm());
    if (k > 0) largest_change = std::max(largest_change, std::abs(e - previous));
    previous = e;
  }
  ASSERT_GT(largest_force, 0.0);  // the spring did reach in
  EXPECT_LT(largest_change, 2.0 * largest_force * 0.0055 * step_angle);
}

// The onset h is 2 % of the mean spring, 0.16 mm here. The strip's middle node lifted clear of
// the cube and its neighbours 0.8 mm under its top: a step dropping the middle node onto the top
// carries the springs to them 0.8 mm × (1 − t) deep under the edges at once, refused; the same
// step from springs already that deep, or a step of a tenth of a millimetre, is admitted.
TEST(SpringContact, AStepThatCarriesASpringDeepInAtOnceIsRefused) {
  const std::vector<Eigen::Vector3d> resting = strip_cutting_edges();
  const Model model = strip_over_cube(resting);
  const SpringContact term(model, {0}, kStiffness);
  std::vector<Eigen::Vector3d> lifted = resting;
  for (Eigen::Vector3d& p : lifted) p.z() += 0.003;
  EXPECT_FALSE(term.step_check(model, lifted)->admits(model, resting));
  EXPECT_TRUE(term.step_check(model, resting)->admits(model, resting));
  EXPECT_TRUE(term.step_check(model, lifted)->admits(model, lifted));
  std::vector<Eigen::Vector3d> nearer = resting;
  for (Eigen::Vector3d& p : nearer) p.z() += 0.0001;
  EXPECT_TRUE(term.step_check(model, nearer)->admits(model, resting));
}

TEST(SpringContact, OnlyNewtonCarriesItAndABadStiffnessIsRefused) {
  const Model model = strip_over_cube(strip_cutting_edges());
  EXPECT_EQ(SpringContact(model, {0}, kStiffness).needs(), SolverNeeds(SolverNeed::stiff_penalty));
  EXPECT_THROW(SpringContact(model, {0}, 0.0), std::invalid_argument);
  EXPECT_THROW(SpringContact(model, {0}, std::nan("")), std::invalid_argument);
  EXPECT_THROW(SpringContact(model, {1}, kStiffness), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::spring_contact_test
