#include "fabform/study/study_cases.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

namespace fabform {
namespace {

// A uniform number in [0, 1) from the top 53 bits.
double unit(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

// Fisher–Yates with an index from the unit number, so no library distribution is involved.
std::vector<int> shuffled(int count, std::mt19937_64& random) {
  std::vector<int> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), 0);
  for (int i = count - 1; i > 0; --i) {
    const auto j = static_cast<int>(std::floor(unit(random) * (i + 1)));
    std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(std::min(j, i))]);
  }
  return order;
}

// Six significant digits: the value the run is given is the value the table shows.
std::string sampled_text(const SampleRange& range, double stratum_position) {
  char text[32];
  if (range.integer) {
    const double span = range.high - range.low + 1.0;
    std::snprintf(text, sizeof text, "%.0f", std::min(range.high, range.low + std::floor(stratum_position * span)));
  } else {
    std::snprintf(text, sizeof text, "%.6g", range.low + stratum_position * (range.high - range.low));
  }
  return text;
}

}  // namespace

std::vector<StudyCase> grid_cases(const std::vector<StudyAxis>& axes) {
  std::vector<StudyCase> cases(1);
  for (const StudyAxis& axis : axes) {
    std::vector<StudyCase> longer;
    for (const StudyCase& partial : cases)
      for (const StudyValue& value : axis.values) {
        StudyCase c = partial;
        c.values.push_back(value);
        longer.push_back(std::move(c));
      }
    cases = std::move(longer);
  }
  return axes.empty() ? std::vector<StudyCase>{} : cases;
}

std::vector<StudyCase> specimen_cases(const std::vector<StudyCase>& cases, int specimens, const SourceLocation& where) {
  std::vector<StudyCase> out;
  out.reserve(cases.size() * static_cast<std::size_t>(std::max(specimens, 0)));
  for (const StudyCase& c : cases)
    for (int k = 1; k <= specimens; ++k) {
      StudyCase specimen = c;
      const std::string seed = std::to_string(k);
      specimen.values.push_back({kSpecimenSeedKey, seed, seed, where});
      out.push_back(std::move(specimen));
    }
  return out;
}

std::vector<StudyCase> latin_hypercube(const std::vector<SampleRange>& ranges, int count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<StudyCase> cases(static_cast<std::size_t>(count));
  for (const SampleRange& range : ranges) {
    const std::vector<int> strata = shuffled(count, random);
    for (int i = 0; i < count; ++i) {
      const double position = (strata[static_cast<std::size_t>(i)] + unit(random)) / count;
      const std::string text = sampled_text(range, position);
      cases[static_cast<std::size_t>(i)].values.push_back({range.key, text, text, range.where});
    }
  }
  return cases;
}

}  // namespace fabform
