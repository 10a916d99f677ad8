// The drape tests of issue 5 on the shipped pin and Cusick scenes: bending against gravity sets
// the drape coefficient between its limits, a soft knit folds on the Cusick disc, and seed 000's
// damped dynamics never gains energy on its way to rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "fabform/analysis/drape_figures.hpp"
#include "fabform/model/potential_energy.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/dynamic.hpp"
#include "fabform/solver/solve.hpp"
#include "test_paths.hpp"

namespace fabform::drape_scenes_test {
namespace {

struct Draped {
  Summary summary;
  DrapeFigures figures;
  double area_flat_m2 = 0.0;    // the fabric's faces flat
  double area_formed_m2 = 0.0;  // and draped
};

// Solves the scene with the solver it names and reads the drape figures as result.json does.
Draped drape(const Scene& scene) {
  const Model model = build_model(scene);
  SolverState state = SolverState::at_start(model);
  Draped out{solve(model, state, scene.solver), {}};
  double support = 0.0;
  for (const RigidBody& body : model.bodies)
    if (body.name() == scene.drape.support) support = support_area(body.mesh());
  const double r = scene.fabric.radius_m();
  out.figures = drape_figures(model.fabric, state.x, scene.origin_m.head<2>() + Eigen::Vector2d(r, r), support);
  out.area_flat_m2 = model.fabric.flat_area();
  for (const Face& face : model.fabric.faces()) out.area_formed_m2 += face_area(face, state.x);
  return out;
}

// The pin scene on a coarse arc mesh (97 nodes), so that a test takes a fraction of a second.
Scene coarse_pin(double bending_N_m) {
  Scene scene = load_scene(test::source_path("scenes/pin.toml"));
  scene.fabric.rings = 6;
  scene.fabric.spokes = 16;
  scene.bending.stiffness_N_m = bending_N_m;
  return scene;
}

// Bend springs resist a kink only to second order in its angle, so even very stiff ones let the
// circle droop a little round the pin: DC approaches 1 as the stiffness grows, 0.89 at 1e6 N/m
// (seed 000's denim weighs 3.2 N/m²). 1e-3 N/m is limp: the circle hangs straight down.
// So stiff a fabric converges slowly (newton: 480 iterations to 1e-5 N) and on this machine's
// BLAS stalls at 1.1e-6 N, short of the scene's 1e-6 N; its DC is settled to 1e-6 by 1e-5 N.
TEST(PinDrape, StiffInBendingStaysNearlyFlat) {
  Scene scene = coarse_pin(1e6);
  scene.solver.newton.tolerance_N = 1e-5;
  const Draped d = drape(scene);
  ASSERT_TRUE(d.summary.converged()) << d.summary.message;
  EXPECT_GT(d.figures.coefficient, 0.85);
  EXPECT_LE(d.figures.coefficient, 1.0);
}

TEST(PinDrape, LimpHangsStraightDown) {
  const Draped d = drape(coarse_pin(1e-3));
  ASSERT_TRUE(d.summary.converged()) << d.summary.message;
  EXPECT_GE(d.figures.coefficient, 0.0);
  EXPECT_LT(d.figures.coefficient, 0.05);
}

TEST(PinDrape, StifferDrapesWider) {
  double previous = -1.0;
  for (const double bending : {1e-1, 1e1, 1e3}) {
    const Draped d = drape(coarse_pin(bending));
    ASSERT_TRUE(d.summary.converged()) << bending << " N/m: " << d.summary.message;
    EXPECT_GT(d.figures.coefficient, previous) << bending << " N/m";
    previous = d.figures.coefficient;
  }
}

// The shipped Cusick scene: the swimwear knit hangs over the disc's edge in folds.
TEST(CusickDrape, SoftKnitFoldsOverTheDisc) {
  const Draped d = drape(load_scene(test::source_path("scenes/cusick.toml")));
  ASSERT_TRUE(d.summary.converged()) << d.summary.message;
  EXPECT_GE(d.figures.folds, 3);
  EXPECT_GT(d.figures.coefficient, 0.0);
  EXPECT_LT(d.figures.coefficient, 0.5);
  EXPECT_EQ(d.figures.shadow_pieces, 1);
}

// The Cusick scene as issue 22 asks its folds to be measured: the compression response that
// buckles (item 2) and a seeded jitter of the start 0.1 mm in z (item 4), meshed as shipped
// (quadrangular, 40 divisions), as rings on spokes (20 on 64: a comparable 1281 nodes) or as the
// lattice with its inner nodes jittered by up to 0.2 of the spacing (the same seed's).
Draped cusick(const std::string& compression, FabricSpec::Mesh mesh = FabricSpec::Mesh::quadrangular, int seed = 1) {
  Scene scene = load_scene(test::source_path("scenes/cusick.toml"), {{"fabric.compression", compression},
                                                                      {"initial.perturbation_m", "1e-4"},
                                                                      {"initial.seed", std::to_string(seed)}});
  scene.fabric.mesh = mesh;
  if (mesh == FabricSpec::Mesh::arc) {
    scene.fabric.rings = 20;
    scene.fabric.spokes = 64;
  }
  if (mesh == FabricSpec::Mesh::jittered) scene.fabric.jitter = kMaxJitter;  // the key's default; the seed is the start's
  return drape(scene);
}

// Tension-only, the overhang gathers in its own plane (the whole specimen loses 12 % of its area in
// the README's run without perturbation; more than 5 % is asserted);
// buckling, it keeps its area (within 1 %) and folds instead.
TEST(CusickDrape, BucklingKeepsTheAreaThatTensionOnlyLoses) {
  const Draped none = cusick("none"), buckling = cusick("buckling");
  ASSERT_TRUE(none.summary.converged()) << none.summary.message;
  ASSERT_TRUE(buckling.summary.converged()) << buckling.summary.message;
  EXPECT_LT(none.area_formed_m2, 0.95 * none.area_flat_m2);
  EXPECT_NEAR(buckling.area_formed_m2, buckling.area_flat_m2, 0.01 * buckling.area_flat_m2);
}

// Without compression and perturbation the quadrangular mesh gave 4 folds and the arc mesh none
// (issue 22). With them a specimen's count depends on its imperfection as a real specimen's does
// (near 9 folds the drape has several rests of nearly equal energy: one seed gives 8 folds on a
// mesh, the next 10), so the count is held as a tester reports it, over specimens: four of each
// mesh, seeds 1 to 4, every one folding at least 7 times and the three meshes' mean counts within
// 1 of each other (docs/drape.md, "Drape": more specimens and a refinement, by tools/drape_meshes.py).
TEST(CusickDrape, FoldCountComesFromTheFabricNotTheMesh) {
  using Mesh = FabricSpec::Mesh;
  constexpr int kSpecimens = 4;
  std::vector<double> means;
  for (const Mesh mesh : {Mesh::quadrangular, Mesh::arc, Mesh::jittered}) {
    double folds = 0.0;
    for (int seed = 1; seed <= kSpecimens; ++seed) {
      const Draped d = cusick("buckling", mesh, seed);
      ASSERT_TRUE(d.summary.converged()) << d.summary.message;
      EXPECT_GE(d.figures.folds, 7) << "mesh " << static_cast<int>(mesh) << ", seed " << seed;
      folds += d.figures.folds;
    }
    means.push_back(folds / kSpecimens);
  }
  const auto [least, most] = std::minmax_element(means.begin(), means.end());
  EXPECT_LE(*most - *least, 1.0) << "mean folds: " << means[0] << ", " << means[1] << ", " << means[2];
}

// Seed 000's damped dynamics: kinetic plus potential energy never rises along the trajectory.
// Symplectic Euler conserves a shadow energy, not this one: it may exceed it by O(Δt) in a step,
// so after the first steps (where the fabric starts from rest) each step may lie above the
// lowest energy so far by at most 1e-6 of the energy the fall releases.
TEST(PinDrape, DynamicsNeverGainsEnergy) {
  Scene scene = coarse_pin(0.5);
  scene.solver.name = "dynamic";
  scene.solver.dynamic.damping = 0.01;
  scene.solver.dynamic.max_iterations = 20000;
  const Model model = build_model(scene);
  SolverState state = SolverState::at_start(model);
  const std::vector<double> masses = node_masses(model, inertia_density(model, scene.solver.dynamic));
  const auto energy = [&] {
    double kinetic = 0.0;
    for (std::size_t k = 0; k < state.velocity.size(); ++k) kinetic += 0.5 * masses[k] * state.velocity[k].squaredNorm();
    return kinetic + potential_energy(model, state.x);
  };
  const double start = energy();
  std::vector<double> history;
  solve(model, state, scene.solver, [&](const IterationRecord&) { history.push_back(energy()); });
  ASSERT_GT(history.size(), 1000u);
  const double released = start - history.back();
  ASSERT_GT(released, 0.0);
  double lowest = history[10];
  for (std::size_t step = 11; step < history.size(); ++step) {
    EXPECT_LE(history[step], lowest + 1e-6 * released) << "step " << step;
    lowest = std::min(lowest, history[step]);
  }
}

}  // namespace
}  // namespace fabform::drape_scenes_test
