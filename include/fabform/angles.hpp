#pragma once
// π and the degree, once: scene keys, layouts, reports and solvers turn degrees and radians.
namespace fabform {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kRadiansPerDegree = kPi / 180.0;
inline constexpr double kDegreesPerRadian = 180.0 / kPi;

}  // namespace fabform
