#pragma once
// The force scale of a fabric: what its springs carry per unit strain at rest, w·dT/dε just
// above ε = 0, the least over its warp and weft springs. A tolerance relative to it,
// ‖R‖∞ / scale, means the same for a stiff denim and a soft knit, which a tolerance in newtons
// does not (seed 003's e = 2.4e-2 N is more than twice every spring's force in a swimwear knit
// at rest on the mold).
#include "fabform/model/model.hpp"

namespace fabform {

/// The force scale (N); 0 for a fabric whose stretch tables start slack.
double spring_force_scale_N(const Model& model);

}  // namespace fabform
