#pragma once
// What a drape test reads off a draped circle: its shadow, the drape coefficient against the
// support disc's shadow (none over a pin), and the folds round its outline.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

struct DrapeFigures {
  double coefficient = 0.0;       // DC = (A_shadow − A_support) / (A_specimen − A_support)
  double shadow_area_m2 = 0.0;    // the draped fabric's shadow on the horizontal plane
  double specimen_area_m2 = 0.0;  // the flat fabric as meshed (so a fabric left flat has DC 1)
  double support_area_m2 = 0.0;   // the support disc's shadow; 0 over a pin
  int folds = 0;                  // lobes of the shadow's largest outline round the centre
  int shadow_pieces = 0;
};

/// The shadow area of a body's triangles (m²), the A_disc of a Cusick test.
double support_area(const TriangleMesh& mesh);

/// The figures of a fabric at positions x, its centre (where the flat circle's centre was
/// placed) at centre_m. A fold counts when the outline's distance from the centre rises and
/// falls by more than 2 % of the fabric's radius, on the largest outline averaged over three
/// cells of a lattice (whose circle's outline is a staircase of cells) and measured against
/// the flat specimen's outline at each angle (a lattice circle is not round): a fabric left
/// flat has none. Throws std::invalid_argument when the support
/// is not smaller than the specimen or a position is not finite.
DrapeFigures drape_figures(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x,
                           const Eigen::Vector2d& centre_m, double support_area_m2);

}  // namespace fabform
