#pragma once
// Where a scene puts a body: the unit its file is in, a scale, a rotation and a translation.
// CAD files are often in mm or inches; a scene always says which, nothing is guessed.
#include <string>

#include <Eigen/Core>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

struct Placement {
  double metres_per_unit = 1.0;                                 // from the file's unit
  double scale = 1.0;                                           // applied in the file's frame
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();       // about x, then y, then z
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();      // applied last

  /// Why the placement cannot be used, or ""; `field` gets the offending field's name.
  std::string invalid_reason(std::string* field = nullptr) const;
};

/// Metres per unit for "m", "cm", "mm", "in"; false for anything else.
bool parse_length_unit(const std::string& unit, double* metres_per_unit);

/// The rotation of `degrees` about x, then y, then z (proper: no reflection).
Eigen::Matrix3d rotation_from_degrees(const Eigen::Vector3d& degrees);

/// Places every vertex of a mesh. Rotations are proper (no reflection), so orientation is kept.
TriangleMesh place(const TriangleMesh& mesh, const Placement& placement);

}  // namespace fabform
