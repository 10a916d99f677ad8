#pragma once
// Values no real fabric has, most often a unit mistake (g/m² typed as kg/m², µN·m as N·m): a
// run goes on, since a study may mean them, but says so with the range real fabrics span.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/error.hpp"

namespace fabform {

/// A fabric property as the model uses it (SI units) and where it was given.
struct GivenValue {
  double value = 0.0;
  SourceLocation where;
};

/// The properties a scene's fabric runs with; absent ones are not checked.
struct FabricValues {
  std::optional<GivenValue> areal_mass_kg_m2;
  std::optional<GivenValue> rigidity_warp_Nm, rigidity_weft_Nm;  // hinges' flexural rigidity
  std::optional<GivenValue> tensile_warp_N_m, tensile_weft_N_m;   // the tables' small-strain slope
  std::optional<GivenValue> shear_rigidity_N_m;                  // G, N/m per radian
  std::optional<GivenValue> bending_hysteresis_warp_N, bending_hysteresis_weft_N;  // 2HB, N·m/m
  std::optional<GivenValue> shear_hysteresis_N_m;                                   // 2HG, N/m
};

/// The range real fabrics span, from gossamer silk to heavy technical cloth (docs/lab-units.md, "Lab units").
struct PlausibleRange {
  double low = 0.0, high = 0.0;
  double shown_scale = 1.0;  // multiplies the SI value into the unit the message shows
  const char* unit = "";
};
PlausibleRange areal_mass_range();
PlausibleRange rigidity_range();
PlausibleRange tensile_range();
PlausibleRange shear_rigidity_range();
PlausibleRange bending_hysteresis_range();
PlausibleRange shear_hysteresis_range();

/// One line per value outside its range: where it was given, the value and the range.
std::vector<std::string> plausibility_warnings(const FabricValues& values);

}  // namespace fabform
