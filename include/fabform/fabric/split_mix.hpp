#pragma once
// Seeded draws that are the same on every machine: a 64-bit SplitMix sequence (Steele, Lea &
// Flood 2014), not the standard library's distributions, whose algorithms differ between
// libraries. The start's perturbation and the jittered mesh draw from it.
#include <cstdint>

namespace fabform {

/// The next number of the sequence whose state is *state.
std::uint64_t split_mix(std::uint64_t* state);

/// Uniform on [−1, 1), from the next number's top 53 bits.
double symmetric_unit(std::uint64_t* state);

}  // namespace fabform
