// A pressure against Laplace's law: a long membrane clamped round its edge and pressed by P
// bulges, away from its short ends, into a cylinder whose cross-section is a circular arc, and
// the tension across it is T = P·R (per unit length of the cylinder). The discrete band of
// straight springs meets T = P·R·cos(α/2), α the angle each spring turns by: 1e-3 here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "fabform/model/pressure.hpp"
#include "fabform/solver/solve.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::pressure_laplace_test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSpan_m = 0.05;     // across, along the warp (x)
constexpr double kLength_m = 0.30;   // along the cylinder, the weft (y)
constexpr double kStiffness_N_m = 200.0;

Model pressed_membrane(double pressure_Pa) {
  Fabric grid({kSpan_m, kLength_m, 20, 60});
  std::vector<AxisMask> locks(static_cast<std::size_t>(grid.node_count()), 0);
  std::vector<Eigen::Vector3d> start(static_cast<std::size_t>(grid.node_count()));
  for (int k = 0; k < grid.node_count(); ++k) {
    Eigen::Vector3d p = grid.rest_position(k);
    // Out of its plane from the start, the way the pressure will push it (a flat membrane has no
    // stiffness across itself).
    p.z() = -1e-3 * std::sin(kPi * p.x() / kSpan_m) * std::sin(kPi * p.y() / kLength_m);
    start[static_cast<std::size_t>(k)] = p;
    if (grid.on_perimeter(k)) locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
  }
  Model model{grid, test::linear_table(kStiffness_N_m), test::linear_table(kStiffness_N_m), locks, {}, start};
  model.terms.push_back(std::make_shared<PressureLoad>(grid, pressure_Pa, Eigen::Vector3d(kSpan_m / 2, kLength_m / 2, 0.0)));
  return model;
}

TEST(PressureLaplace, MidSpanTensionIsPressureTimesRadius) {
  for (const double pressure_Pa : {500.0, 2000.0}) {
    const Model model = pressed_membrane(pressure_Pa);
    SolverState state = SolverState::at_start(model);
    SolverSpec spec;
    spec.name = "newton";
    spec.newton.tolerance_N = 1e-9;
    const Summary s = solve(model, state, spec);
    ASSERT_EQ(s.termination, Termination::converged) << s.message;
    // The cross-section half way along: its edge, middle and other edge nodes give the arc's
    // radius from chord and sag; the middle warp spring its tension.
    const Fabric& grid = model.fabric;
    const auto at = [&](int i) { return state.x[static_cast<std::size_t>(grid.node(i, 30))]; };
    const double chord = (at(20) - at(0)).norm();
    const double sag = std::abs(at(10).z() - at(0).z());
    const double radius = chord * chord / (8.0 * sag) + sag / 2.0;
    const double strain = (at(11) - at(10)).norm() / grid.spacing_warp() - 1.0;
    const double tension = kStiffness_N_m * strain;
    EXPECT_NEAR(tension, pressure_Pa * radius, 0.01 * pressure_Pa * radius) << "P = " << pressure_Pa << " Pa";
    // It bulges the way the pressure pushes: down, for a fabric face up.
    EXPECT_LT(at(10).z(), -0.1 * kSpan_m);
    std::printf("laplace: P = %.0f Pa, T = %.5f N/m, P*R = %.5f N/m, %d newton iterations\n", pressure_Pa, tension,
                pressure_Pa * radius, s.iterations);
  }
}

}  // namespace
}  // namespace fabform::pressure_laplace_test
