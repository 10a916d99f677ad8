#include "fabform/fabric/start_perturbation.hpp"

#include "fabform/fabric/split_mix.hpp"

namespace fabform {

void perturb_start(const StartPerturbation& perturbation, const std::vector<AxisMask>& locks,
                   std::vector<Eigen::Vector3d>* start) {
  if (perturbation.amplitude_m == 0.0) return;
  std::uint64_t state = perturbation.seed;
  for (std::size_t k = 0; k < start->size(); ++k) {
    const double draw = symmetric_unit(&state);  // drawn for every node, so a lock moves no other node's draw
    if (!(locks[k] & kLockZ)) (*start)[k].z() += perturbation.amplitude_m * draw;
  }
}

}  // namespace fabform
