#pragma once
// What a forming engineer reads off each cell (face) of the formed fabric: its shear angle, the
// change of the angle between its warp and its weft from the flat fabric's, in degrees (positive
// where the angle closes); its thickness ratio h/h0 = A0/A, the fabric's volume being constant
// (a cell stretched to twice its area is half as thick); and a wrinkle risk where the cell is
// sheared past the fabric's locking angle (it can shear no further and must buckle) or is
// compressed in both directions (nothing in its plane takes the excess).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

struct CellDeformationOptions {
  double locking_angle_deg = 45.0;     // a cell sheared further locks (from the shear table or the scene)
  double compression_strain = 1e-3;    // both mean strains below −this: compressed both ways
  /// Why these options cannot be used, or "".
  std::string invalid_reason() const;
};

struct CellDeformation {
  std::vector<double> shear_angle_deg;       // per face; NaN where a face lacks warp or weft sides
  std::vector<double> thickness_ratio;       // per face; NaN where a face has collapsed
  std::vector<unsigned char> wrinkle_risk;   // per face: 1 locked or compressed both ways
  double shear_angle_max_deg = 0.0;          // the largest |shear angle|
  int shear_angle_max_face = -1;
  double thickness_ratio_min = 1.0;          // the smallest ratio (the most thinned cell)
  int thickness_ratio_min_face = -1;
  int wrinkle_cells = 0;
};

/// Each face's deformation at `x`; throws std::invalid_argument for invalid options.
CellDeformation cell_deformation(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                 const CellDeformationOptions& options);

}  // namespace fabform
