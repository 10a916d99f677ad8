#pragma once
// |x| with its corner rounded over a width w (Huber): x²/(2w) inside, |x| − w/2 beyond, joined
// with their slopes. The friction terms' energies (a moment or a force times a turn or a shear)
// are |·| on the KES loops' loading branch; the rounding keeps them smooth for Newton, and inside
// it the friction grows from 0, the stick.
#include <cmath>

namespace fabform {

inline double rounded_abs(double x, double width) {
  const double a = std::abs(x);
  return a < width ? 0.5 * a * a / width : a - 0.5 * width;
}

/// d/dx: x/w inside, ±1 beyond.
inline double rounded_abs_slope(double x, double width) {
  return std::abs(x) < width ? x / width : (x > 0.0 ? 1.0 : -1.0);
}

/// d²/dx²: 1/w inside, 0 beyond.
inline double rounded_abs_curvature(double x, double width) { return std::abs(x) < width ? 1.0 / width : 0.0; }

}  // namespace fabform
