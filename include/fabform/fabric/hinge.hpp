#pragma once
// A bending hinge: two faces of the fabric that share a side. Bending the fabric across that
// side turns one face against the other by an angle θ, which the hinge's energy penalises as
// B·(|e|² / (A₁ + A₂))·θ² for small θ (Grinspun et al. 2003; the form taken is Bergou's, in
// hinge_bending.hpp), B the fabric's flexural rigidity (N·m): for four-sided cells bent across a
// side, B·κ²/2 per area. Between two triangles (only round an arc mesh's centre) the same
// formula is stiffer than the continuum, by about 2× on equilateral triangles. A four-sided
// face's far side stands in for its far corner: its midpoint, the mean of two nodes.
#include <array>

namespace fabform {

struct Hinge {
  std::array<int, 2> edge = {0, 0};  // the shared side's nodes
  // Each face's far point as the mean of two nodes (a triangle's far corner twice).
  std::array<std::array<int, 2>, 2> wing = {{{0, 0}, {0, 0}}};
  double shape_factor = 0.0;  // |e|² / (A₁ + A₂) in the flat fabric (dimensionless)
  // The weights (1/m) of the edge's two nodes and the two far points in the hinge's bend
  // vector Σ wᵢ·pᵢ: the affine dependency of the four points in the flat fabric, scaled so a
  // far point's weight times its distance from the edge is 1 (see hinge_bending.hpp).
  std::array<double, 4> weight = {0.0, 0.0, 0.0, 0.0};
};

}  // namespace fabform
