#pragma once
// The cases of a study: every combination of values (a full grid), or a space-filling sample
// of ranges (a Latin hypercube), reproducible from its seed.
#include <cstdint>
#include <string>
#include <vector>

#include "fabform/study/study_spec.hpp"

namespace fabform {

/// A varied key and its values, in the order given.
struct StudyAxis {
  std::string key;
  std::vector<StudyValue> values;
};

/// Every combination, the last axis changing fastest (as nested loops would write them).
std::vector<StudyCase> grid_cases(const std::vector<StudyAxis>& axes);

/// The seed of a specimen's imperfection: the key a study with specimens varies last.
inline constexpr const char* kSpecimenSeedKey = "initial.seed";
/// The most specimens a study may test of each case.
inline constexpr int kMaxSpecimens = 1000;

/// Every case `specimens` times in a row, the k-th with initial.seed = k (1 … specimens).
std::vector<StudyCase> specimen_cases(const std::vector<StudyCase>& cases, int specimens, const SourceLocation& where);

/// A sampled key: a closed range; whole numbers only when both ends are TOML integers.
struct SampleRange {
  std::string key;
  double low = 0.0;
  double high = 0.0;
  bool integer = false;
  SourceLocation where;
};

/// `count` cases, each range cut into `count` equal strata and every stratum used once per key
/// (Latin hypercube), the strata paired at random and each value drawn within its stratum.
/// The same seed gives the same cases on every machine: std::mt19937_64 is fully specified,
/// and its bits are turned into numbers here, not by the library's distributions.
std::vector<StudyCase> latin_hypercube(const std::vector<SampleRange>& ranges, int count, std::uint64_t seed);

}  // namespace fabform
