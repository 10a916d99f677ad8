#include "fabform/scene/fabric_plausibility.hpp"

#include <cstdio>

#include "fabform/model/gravity.hpp"

namespace fabform {

// Apparel and technical fabrics weigh 15–1500 g/m² (chiffon to heavy canvas and glass cloth);
// KES-FB2 bending rigidities run 0.002–10 gf·cm²/cm (0.2–1000 µN·m); small-strain tension per
// width 10 N/m (a loose knit) to 5e6 N/m (a glass or carbon weave); KES-FB1 shear rigidity
// 0.05–30 gf/cm/° (3–1700 N/m); KES-FB2's bending hysteresis 2HB 0.002–2 gf·cm/cm and KES-FB1's
// shear hysteresis 2HG 0.05–15 gf/cm (a sheer silk to a stiff cotton canvas). Each range is
// widened by a factor past these so that only a value no fabric has, most often a unit slip of
// 1000 or 1e6, is flagged.
PlausibleRange areal_mass_range() { return {5e-3, 3.0, 1e3, "g/m²"}; }
PlausibleRange rigidity_range() { return {5e-8, 5e-3, 1e6, "µN·m"}; }
PlausibleRange tensile_range() { return {2.0, 2e7, 1.0, "N/m"}; }
PlausibleRange shear_rigidity_range() { return {0.5, 1e4, 1.0, "N/m per radian"}; }
PlausibleRange bending_hysteresis_range() {
  return {5e-4 * kNewtonsPerGramForce, 20.0 * kNewtonsPerGramForce, 1.0 / kNewtonsPerGramForce, "gf·cm/cm"};
}
PlausibleRange shear_hysteresis_range() {
  return {0.01 * kGramForcePerCentimetre_N_m, 100.0 * kGramForcePerCentimetre_N_m, 1.0 / kGramForcePerCentimetre_N_m, "gf/cm"};
}

namespace {

void check(const std::optional<GivenValue>& given, const char* what, const PlausibleRange& range,
           std::vector<std::string>* warnings) {
  if (!given || (given->value >= range.low && given->value <= range.high)) return;
  char text[300];
  std::snprintf(text, sizeof text, "%s %.4g %s lies outside the range of real fabrics, %.4g to %.4g %s: check its unit",
                what, given->value * range.shown_scale, range.unit, range.low * range.shown_scale,
                range.high * range.shown_scale, range.unit);
  warnings->push_back(format_located(given->where, text));
}

}  // namespace

std::vector<std::string> plausibility_warnings(const FabricValues& values) {
  std::vector<std::string> warnings;
  check(values.areal_mass_kg_m2, "the areal mass", areal_mass_range(), &warnings);
  check(values.rigidity_warp_Nm, "the warp's flexural rigidity", rigidity_range(), &warnings);
  check(values.rigidity_weft_Nm, "the weft's flexural rigidity", rigidity_range(), &warnings);
  check(values.tensile_warp_N_m, "the warp's small-strain tension per width per strain", tensile_range(), &warnings);
  check(values.tensile_weft_N_m, "the weft's small-strain tension per width per strain", tensile_range(), &warnings);
  check(values.shear_rigidity_N_m, "the shear rigidity G", shear_rigidity_range(), &warnings);
  check(values.bending_hysteresis_warp_N, "the warp's bending hysteresis 2HB", bending_hysteresis_range(), &warnings);
  check(values.bending_hysteresis_weft_N, "the weft's bending hysteresis 2HB", bending_hysteresis_range(), &warnings);
  check(values.shear_hysteresis_N_m, "the shear hysteresis 2HG", shear_hysteresis_range(), &warnings);
  return warnings;
}

}  // namespace fabform
