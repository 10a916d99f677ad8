#include "fabform/material/compression_response.hpp"

#include "fabform/angles.hpp"

namespace fabform {
namespace {


}  // namespace

bool parse_compression(const std::string& name, Compression* mode) {
  if (name == "none") *mode = Compression::none;
  else if (name == "linear") *mode = Compression::linear;
  else if (name == "buckling") *mode = Compression::buckling;
  else return false;
  return true;
}

const char* to_string(Compression mode) {
  switch (mode) {
    case Compression::none: return "none";
    case Compression::linear: return "linear";
    case Compression::buckling: return "buckling";
  }
  return "none";
}

double euler_buckling_tension(double flexural_rigidity_Nm, double length_m) {
  return kPi * kPi * flexural_rigidity_Nm / (length_m * length_m);
}

// Compared on tension, not strain, so that k₀ = 0 (a table that starts slack) never divides.
bool CompressionLaw::buckled(double strain) const {
  return mode == Compression::buckling && stiffness_N_per_m * strain < -buckling_tension_N_per_m;
}

double CompressionLaw::energy_density(double strain) const {
  if (mode == Compression::none) return 0.0;
  if (!buckled(strain)) return 0.5 * stiffness_N_per_m * strain * strain;
  const double eb = buckling_strain(), past = eb - strain, tb = buckling_tension_N_per_m;
  return 0.5 * stiffness_N_per_m * eb * eb + tb * past + 0.25 * tb * past * past;
}

double CompressionLaw::tension(double strain) const {
  if (mode == Compression::none) return 0.0;
  if (!buckled(strain)) return stiffness_N_per_m * strain;
  return -buckling_tension_N_per_m * (1.0 + 0.5 * (buckling_strain() - strain));
}

double CompressionLaw::slope(double strain) const {
  if (mode == Compression::none) return 0.0;
  return buckled(strain) ? 0.5 * buckling_tension_N_per_m : stiffness_N_per_m;
}

}  // namespace fabform
