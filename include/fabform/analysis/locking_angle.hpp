#pragma once
// A fabric's locking angle from its shear table (the diagonal springs' tension against the
// diagonal's strain e, seed 004). Read as a picture-frame curve is: where the tangent of its
// first segment meets the tangent of its last (the shear where the soft start gives way to the
// stiff, locked end). A diagonal of a square cell sheared by γ stretches to √(2 + 2 sin γ) of
// its side, so e = √(1 + sin γ) − 1 and γ = asin((1 + e)² − 1).
#include <optional>

#include "fabform/material/tension_table.hpp"

namespace fabform {

/// The shear angle (degrees) of a diagonal strain; strains beyond a square cell's full shear
/// (e ≥ √2 − 1) give 90.
double shear_angle_of_diagonal_strain_deg(double diagonal_strain);

/// The table's locking angle; none when the table does not stiffen (its last segment no steeper
/// than its first) or has a single segment.
std::optional<double> locking_angle_deg(const TensionTable& shear);

}  // namespace fabform
