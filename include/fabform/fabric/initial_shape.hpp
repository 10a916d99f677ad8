#pragma once
// Seed 003 releases the fabric from an initial deformation clear of the body. These are the
// shapes a scene can ask for; each maps the flat grid, placed with its lower-left corner at
// `origin`, to starting positions.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"

namespace fabform {

struct InitialShape {
  // pattern: each panel of a garment where its pattern places it (PanelSpec's placement), the
  // origin added; it takes no parameter.
  enum class Kind { flat, lift, bump, wrap, tube, fold, pattern };
  Kind kind = Kind::flat;
  double height_m = 0.0;  // lift: interior nodes raised by this; bump: peak of a sine bump
  // wrap: the warp runs round a vertical (z) axis through axis_xy_m, on a circle of radius
  // radius_m, spanning span_deg centred on the direction facing_deg (0 = +x, 90 = +y); the
  // weft stays vertical, starting at the origin's z.
  // fold: the fabric folded over across the warp at fold_at_m (from its left edge): the part
  // beyond laid back over the part before, height_m above it (a napkin folded in two).
  double fold_at_m = 0.0;
  // tube: a tube fabric's round direction once round the axis on that circle, its seam facing
  // facing_deg, its length vertical from the origin's z.
  Eigen::Vector2d axis_xy_m = Eigen::Vector2d::Zero();
  double radius_m = 0.0;
  double facing_deg = 0.0;
  double span_deg = 0.0;

  /// Why the parameters cannot be used, or ""; `field` gets the offending parameter's name.
  std::string invalid_reason(std::string* field = nullptr) const;
};

bool parse_initial_kind(const std::string& name, InitialShape::Kind* kind);

std::vector<Eigen::Vector3d> initial_positions(const Fabric& grid,
                                               const Eigen::Vector3d& origin,
                                               const InitialShape& shape);

}  // namespace fabform
