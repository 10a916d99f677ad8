#include "fabform/fabric/start_perturbation.hpp"

namespace fabform {
namespace {

// SplitMix64 (Steele, Lea & Flood 2014): a fixed, portable sequence for a given seed.
std::uint64_t split_mix(std::uint64_t* state) {
  std::uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Uniform on [−1, 1) from the top 53 bits.
double symmetric_unit(std::uint64_t* state) {
  return 2.0 * static_cast<double>(split_mix(state) >> 11) * 0x1.0p-53 - 1.0;
}

}  // namespace

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
