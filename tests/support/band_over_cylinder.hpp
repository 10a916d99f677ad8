#pragma once
// A band over a horizontal cylinder through half a turn, its tails hanging straight down: end A
// (column 0) held, end B (the last column) held pulled down by `pull_m`. 60 warp springs round
// the wrap (3° each) on a 2048-facet cylinder of radius 5 cm, a linear 200 N/m table. Frictionless
// its tension is one T all along (the capstan test), and the wrap presses p = T / r (Laplace).
#include <cmath>

#include "fabform/geometry/rigid_body.hpp"
#include "fabform/model/model.hpp"
#include "fabform/solver/solver_state.hpp"
#include "support/clamped_fabric.hpp"
#include "support/shapes.hpp"

namespace fabform::test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius_m = 0.05;
constexpr double kSpacing_m = kPi * kRadius_m / 60.0;  // 60 springs round the wrap
constexpr int kTailSprings = 20;
constexpr double kWidth_m = 0.02;

// Arc length s along the band from end A (s = 0) to its point: up the left tail, over the top
// from φ = π to 0, down the right tail.
inline Eigen::Vector3d along_band(double s, double y) {
  const double tail = kTailSprings * kSpacing_m;
  const double arc = kPi * kRadius_m;
  if (s <= tail) return {-kRadius_m, y, s - tail};
  if (s <= tail + arc) {
    const double phi = kPi - (s - tail) / kRadius_m;
    return {kRadius_m * std::cos(phi), y, kRadius_m * std::sin(phi)};
  }
  return {kRadius_m, y, -(s - tail - arc)};
}

struct BandOverCylinder {
  Model model;

  BandOverCylinder(double friction, double pull_m) : model(build(friction, pull_m)) {}

  static Model build(double friction, double pull_m) {
    const int springs = 2 * kTailSprings + 60;
    Fabric band({springs * kSpacing_m, kWidth_m, springs, 1});
    std::vector<AxisMask> locks(static_cast<std::size_t>(band.node_count()), 0);
    std::vector<Eigen::Vector3d> start(static_cast<std::size_t>(band.node_count()));
    for (int k = 0; k < band.node_count(); ++k) {
      const auto i = static_cast<std::size_t>(k);
      start[i] = along_band(band.i_of(k) * kSpacing_m, band.j_of(k) * kWidth_m);
      if (band.i_of(k) == 0 || band.i_of(k) == springs) locks[i] = kLockX | kLockY | kLockZ;
      if (band.i_of(k) == springs) start[i].z() -= pull_m;
    }
    std::vector<RigidBody> bodies;
    bodies.emplace_back("cylinder", cylinder_along_y(kRadius_m, -0.1, 0.2, 2048), friction);
    return Model{band, linear_table(200.0), linear_table(200.0), locks, std::move(bodies), start};
  }

  // The pull on the held ends: their springs' tension, summed across the band.
  double end_tension(int column) const {
    double total = 0.0;
    for (int k = 0; k < model.node_count(); ++k)
      if (model.fabric.i_of(k) == column) total += node_force(model, state.x, k).norm();
    return total;
  }

  SolverState state = SolverState::at_start(model);
};

}  // namespace fabform::test
