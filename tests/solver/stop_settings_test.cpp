// StopSettings::invalid_reason, the one check of what stops a run for every solver: each bad
// value named by its field, over the values at and beyond each bound; and every solver's options
// refusing the same values through it (the registry's solvers, relax, dynamic and newton).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "fabform/solver/dynamic.hpp"
#include "fabform/solver/newton.hpp"
#include "fabform/solver/relax.hpp"
#include "fabform/solver/stop_settings.hpp"

namespace fabform::stop_settings_test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

StopSettings valid() { return {1e-6, 0.0, 100}; }

std::string field_of(const StopSettings& stop) {
  std::string field;
  EXPECT_NE(stop.invalid_reason(&field), "");
  return field;
}

TEST(StopSettings, AcceptsTheBoundsThemselves) {
  EXPECT_EQ(valid().invalid_reason(), "");
  StopSettings s = valid();
  s.tolerance_m = 0.0, s.max_iterations = 0;  // no distance; no iteration (the start measured)
  EXPECT_EQ(s.invalid_reason(), "");
  s.tolerance_N = std::numeric_limits<double>::denorm_min(), s.tolerance_m = 1e300;
  EXPECT_EQ(s.invalid_reason(), "");
}

TEST(StopSettings, NamesEachBadField) {
  for (const double bad : {0.0, -1e-6, kNaN, kInf}) {
    StopSettings s = valid();
    s.tolerance_N = bad;
    EXPECT_EQ(field_of(s), "tolerance_N") << bad;
  }
  for (const double bad : {-1e-9, kNaN, kInf}) {
    StopSettings s = valid();
    s.tolerance_m = bad;
    EXPECT_EQ(field_of(s), "tolerance_m") << bad;
  }
  StopSettings s = valid();
  s.max_iterations = -1;
  EXPECT_EQ(field_of(s), "max_iterations");
}

template <class Options>
std::string options_field(const StopSettings& stop) {
  Options options;
  set_stop_settings(options, stop);
  std::string field;
  options.invalid_reason(&field);
  return field;
}

TEST(StopSettings, EverySolverRefusesThemAlike) {
  for (StopSettings bad : {StopSettings{0.0, 0.0, 1}, StopSettings{1e-6, kNaN, 1}, StopSettings{1e-6, 0.0, -1}}) {
    const std::string field = field_of(bad);
    EXPECT_EQ(options_field<RelaxOptions>(bad), field);
    EXPECT_EQ(options_field<DynamicOptions>(bad), field);
    EXPECT_EQ(options_field<NewtonOptions>(bad), field);
  }
}

}  // namespace
}  // namespace fabform::stop_settings_test
