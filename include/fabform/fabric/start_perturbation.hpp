#pragma once
// A small seeded out-of-plane jitter of the fabric's start (issue 22, item 4): a perfectly flat,
// symmetric start lets the mesh's own symmetry choose how a drape folds (the quadrangular lattice
// 4 folds, the arc mesh none); an imperfection, as every real specimen has, lets the fabric's
// stiffness and weight choose. Each node not held in z moves along z by a uniform draw from
// [−a, a], the same for a given seed on every machine (split_mix.hpp).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/node_set.hpp"

namespace fabform {

struct StartPerturbation {
  double amplitude_m = 0.0;  // a: the largest move along z; 0, the default: no perturbation
  std::uint64_t seed = 1;
};

/// Moves every node whose z is free by its draw; `locks` has one entry per node.
void perturb_start(const StartPerturbation& perturbation, const std::vector<AxisMask>& locks,
                   std::vector<Eigen::Vector3d>* start);

}  // namespace fabform
