// Coulomb friction against the capstan equation: a band over a cylinder through an angle θ,
// pulled at one end while the other is held, slides when the tensions' ratio reaches e^{μθ}
// (Euler–Eytelwein), and holds that ratio while it slides. The band here wraps half a turn
// (θ = π) over a horizontal cylinder, its tails hanging straight down; end A is held and end
// B is pulled down by δ, so the whole wrap slides toward B. Newton with friction reaches the
// ratio within 1 % (the discrete band's own error, from its 3° polygon, is 2e-4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fabform/geometry/rigid_body.hpp"
#include "fabform/model/equilibrium.hpp"
#include "fabform/output/checkpoint.hpp"
#include "fabform/solver/solve.hpp"
#include "support/band_over_cylinder.hpp"
#include "support/temp_dir.hpp"

namespace fabform::capstan_test {
namespace {

using Capstan = test::BandOverCylinder;
using test::kPi;

TEST(Capstan, SlidingBandHoldsTheRatioEToTheMuTheta) {
  for (const double mu : {0.1, 0.3}) {
    Capstan capstan(mu, 0.01);
    SolverSpec spec;
    spec.name = "newton";
    spec.newton.tolerance_N = 1e-9;
    spec.newton.max_iterations = 200;
    const Summary s = solve(capstan.model, capstan.state, spec);
    ASSERT_EQ(s.termination, Termination::converged) << s.message;
    const double held = capstan.end_tension(0);
    const double pulled = capstan.end_tension(capstan.model.fabric.nodes_warp() - 1);
    ASSERT_GT(held, 1e-3 * pulled) << "the held end must carry tension for the ratio to mean anything";
    EXPECT_NEAR(pulled / held, std::exp(mu * kPi), 0.01 * std::exp(mu * kPi)) << "mu = " << mu;
    // The wrap slides: every node on the cylinder is at its cone's edge.
    const EquilibriumReport check = measure_equilibrium(capstan.model, capstan.state.x, 1e-7, 1e-6);
    EXPECT_GE(check.contact_nodes, 2 * 55);  // the wrap's 59 nodes a side, less a few at its ends
    std::printf("capstan: mu = %.2f, ratio %.5f, e^(mu pi) %.5f, %d newton iterations\n", mu, pulled / held,
                std::exp(mu * kPi), s.iterations);
    EXPECT_EQ(check.stuck_nodes, 0);
  }
}

// Friction's anchors travel in the checkpoint: a run stopped after 20 Newton iterations and
// resumed from its checkpoint file slides on to the uninterrupted run's rest, bit for bit.
TEST(Capstan, ResumedRunEndsBitForBitWhereTheWholeRunEnds) {
  SolverSpec spec;
  spec.name = "newton";
  spec.newton.tolerance_N = 1e-9;
  Capstan whole(0.3, 0.01);
  ASSERT_TRUE(solve(whole.model, whole.state, spec).converged());

  Capstan part(0.3, 0.01);
  spec.newton.max_iterations = 20;
  const Summary stopped = solve(part.model, part.state, spec);
  ASSERT_EQ(stopped.iterations, 20);
  test::TempDir dir;
  const std::string file = dir.write("checkpoint.bin", checkpoint_bytes(part.state, stopped));
  Checkpoint taken_up = read_checkpoint(file, part.model.node_count(), 1);
  spec.newton.max_iterations = 200;
  ASSERT_TRUE(solve(part.model, taken_up.state, spec, {}, taken_up.summary).converged());
  ASSERT_EQ(taken_up.state.x.size(), whole.state.x.size());
  for (std::size_t k = 0; k < whole.state.x.size(); ++k) EXPECT_EQ(taken_up.state.x[k], whole.state.x[k]) << k;
}

// Without friction the band's tension is the same on both sides of the cylinder.
TEST(Capstan, FrictionlessBandCarriesOneTension) {
  Capstan capstan(0.0, 0.01);
  SolverSpec spec;
  spec.name = "newton";
  spec.newton.tolerance_N = 1e-8;  // on the faceted cylinder its line search stalls near 2e-9 N
  const Summary s = solve(capstan.model, capstan.state, spec);
  ASSERT_EQ(s.termination, Termination::converged) << s.message;
  const double pulled = capstan.end_tension(capstan.model.fabric.nodes_warp() - 1);
  EXPECT_NEAR(capstan.end_tension(0) / pulled, 1.0, 1e-3);
}

}  // namespace
}  // namespace fabform::capstan_test
