#pragma once
// What a tension-only table (one measured in tension alone) gives below zero strain, chosen per
// scene by [fabric] compression (issue 22, item 2). A fabric resists in-plane compression until
// it buckles out of its plane; with "none" a compressed spring is slack, so a drape's overhang
// can gather in its own plane for nothing instead of folding against its bending stiffness.
//
// - none: T = 0 (the tables' own meaning, materials/README.md).
// - linear: T = k₀ ε, k₀ the table's first slope (its small-strain stiffness) continued.
// - buckling: the spring is a strut of its rest length L and the fabric's flexural rigidity B
//   (N·m, per width). It resists with k₀ until it carries Euler's load of a pin-ended strut,
//   T_b = π² B / L² per width, at ε_b = −T_b / k₀; beyond, it bows out of plane and follows the
//   elastica's post-buckling branch to first order, P / P_cr = 1 + Δ / (2L) (Timoshenko & Gere,
//   Theory of Elastic Stability, §2.7: P/P_cr = (2K(k)/π)² ≈ 1 + k²/2 with end shortening
//   Δ/L = 2 − 2E(k)/K(k) ≈ k²), Δ/L = ε_b − ε the shortening past buckling:
//   T = −T_b (1 + (ε_b − ε)/2). The force stays near the plateau (+17 % at Δ/L = 0.34, where the
//   exact elastica gives +21 %) and the stiffness T_b/2 stays positive, as in Choi & Ko's
//   "Stable but responsive cloth" (SIGGRAPH 2002), whose compressed springs buckle into an arc
//   and carry a force set by the bending rigidity rather than by the in-plane stiffness.
//   Energy per rest area Ψ = ∫₀^ε T: ½ k₀ ε² down to ε_b; below it
//   Ψ = ½ k₀ ε_b² + T_b (ε_b − ε) + ¼ T_b (ε_b − ε)², whose ε-derivative is T and second
//   derivative T_b/2 (tests/material/compression_response_test.cpp checks both).
#include <string>

namespace fabform {

enum class Compression { none, linear, buckling };

/// Parses "none", "linear", "buckling"; false for anything else.
bool parse_compression(const std::string& name, Compression* mode);
const char* to_string(Compression mode);

/// The response of one compressed spring (strain ≤ 0): energy per rest area, tension per width
/// and its slope, consistent as derivatives of one another.
struct CompressionLaw {
  Compression mode = Compression::none;
  double stiffness_N_per_m = 0.0;         // k₀: the table's first slope
  double buckling_tension_N_per_m = 0.0;  // T_b: Euler's load per width (buckling only)

  double energy_density(double strain) const;  // J/m²
  double tension(double strain) const;         // N/m, negative in compression
  double slope(double strain) const;           // N/m per unit strain

 private:
  bool buckled(double strain) const;
  double buckling_strain() const { return -buckling_tension_N_per_m / stiffness_N_per_m; }
};

/// Euler's load per width of a pin-ended strut of flexural rigidity B (N·m) and length L (m):
/// π² B / L² (N/m).
double euler_buckling_tension(double flexural_rigidity_Nm, double length_m);

}  // namespace fabform
