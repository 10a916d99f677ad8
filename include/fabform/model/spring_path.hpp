#pragma once
// The way each spring runs between its nodes: straight (seed 003), or, where it passes under an
// edge of a body that lets springs wrap its edges, over that edge (edge_wrap.hpp). Everything
// that reads a spring's length, force or energy from positions reads it here, so strains, forces
// and energies agree on the path. Bend springs span two cells, not fabric: they never wrap.
#include <optional>

#include <Eigen/Core>

#include "fabform/geometry/edge_wrap.hpp"
#include "fabform/model/model.hpp"

namespace fabform {

/// The wrap over the body edge that lengthens the spring most, when it passes under one.
std::optional<EdgeWrap> spring_wrap(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                                    const Eigen::Vector3d& xb);

/// The path's length l and strain l/L − 1.
double spring_path_length(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                          const Eigen::Vector3d& xb);
double spring_path_strain(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                          const Eigen::Vector3d& xb);

/// The spring's energy w·L·Ψ(ε) along its path.
double spring_path_energy(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                          const Eigen::Vector3d& xb);

/// The force it exerts on its end `end` (spring.a or spring.b), its ends at xa and xb. The path
/// is found from a to b whichever end is asked, so both ends' forces and the energy agree on it.
Eigen::Vector3d spring_path_force(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                                  const Eigen::Vector3d& xb, int end);

}  // namespace fabform
