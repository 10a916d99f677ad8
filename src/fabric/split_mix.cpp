#include "fabform/fabric/split_mix.hpp"

namespace fabform {

std::uint64_t split_mix(std::uint64_t* state) {
  std::uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double symmetric_unit(std::uint64_t* state) {
  return 2.0 * static_cast<double>(split_mix(state) >> 11) * 0x1.0p-53 - 1.0;
}

}  // namespace fabform
