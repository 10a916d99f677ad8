#pragma once
// The solvers' common contact problem, and how two solvers' answers to it are compared.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "fabform/model/potential_energy.hpp"
#include "fabform/solver/solver_state.hpp"
#include "support/clamped_fabric.hpp"
#include "support/shapes.hpp"

namespace fabform::test {

inline double max_distance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, (a[k] - b[k]).norm());
  return worst;
}

// A sphere of 3 cm radius whose 320 segments make facets of 0.6 mm meeting at ridges 1.1° apart,
// poles sideways so the fabric meets regular facets. On a faceted body the rest is not unique:
// a node pressed onto a ridge balances on either facet next to it, a fraction of a facet from
// the ridge, and the two solvers may pick different sides (measured: 5e-5 m apart with 160
// segments, 1e-5 m with 640). So their answers are compared within a twentieth of a facet,
// and their energies within 1e-6 of each other: rests on different sides of ridges are
// different local minima (measured: 1.6e-7 apart for newton's harsh and gentle starts, 1e-12
// when the two pick the same sides; which they pick moves with the last bits of a step).
constexpr double kSphereRadius = 0.03;
constexpr int kSphereSegments = 320;
constexpr double kFacet = 2.0 * 3.14159265358979 * kSphereRadius / kSphereSegments;

inline Model fabric_over_sphere(double lift) {
  Model model = clamped_fabric(20, 0.1);
  lift_interior(model, lift);
  model.bodies.emplace_back("sphere", test::sideways_sphere({0.05, 0.05, -0.02}, kSphereRadius,
                                                            kSphereSegments / 2, kSphereSegments));
  return model;
}

inline void expect_same_rest(const Model& model, const SolverState& a, const SolverState& b) {
  EXPECT_LE(max_distance(a.x, b.x), kFacet / 20.0);
  const double energy = potential_energy(model, a.x);
  EXPECT_NEAR(potential_energy(model, b.x), energy, 1e-6 * energy);
}

}  // namespace fabform::test
