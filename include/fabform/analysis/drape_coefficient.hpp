#pragma once
// The drape coefficient of a Cusick drape test: a circular specimen lies on a horizontal disc
// (or over a pin) and the share of its overhang still seen in the shadow of the draped fabric is
// DC = (A_shadow − A_disc) / (A_specimen − A_disc). The shadow is the union of the fabric's
// triangles projected on the horizontal plane (x, y; z is up), computed exactly.
#include <array>
#include <vector>

#include <Eigen/Core>

namespace fabform {

/// The shadow of a draped fabric on the horizontal plane.
struct Shadow {
  double area_m2 = 0.0;      // of the union of the projected triangles, holes left out
  int components = 0;        // connected pieces (two meeting at a single point make one)
  int holes = 0;             // uncovered islands inside the pieces
  /// Corners of the pieces' outer boundaries. Points inside an exactly straight run (a triangle's
  /// corner on another's edge) are left out; points an ulp off the line are corners.
  int outline_vertices = 0;
  /// Each piece's outer boundary, counter-clockwise, one point per corner (x, y in m).
  std::vector<std::vector<Eigen::Vector2d>> outlines;
};

/// The shadow of the triangles (node indices into `positions_m`) projected on z = 0. Triangles
/// that project to zero area (seen edge-on) cast none. Throws std::invalid_argument naming the
/// node when a position is not finite, or the triangle when it names a node that does not exist.
Shadow fabric_shadow(const std::vector<Eigen::Vector3d>& positions_m,
                     const std::vector<std::array<int, 3>>& triangles);

/// The folds (lobes) of a draped fabric seen in an outline: the maxima of the outline's distance
/// from `centre_m` walking round it, a maximum counting once the distance has risen and then
/// fallen by more than `min_depth_m` (0: every strict maximum). Fewer than 3 points have none.
/// Throws std::invalid_argument when `min_depth_m` is negative or not finite.
int count_folds(const std::vector<Eigen::Vector2d>& outline_m, const Eigen::Vector2d& centre_m,
                double min_depth_m = 0.0);

/// DC = (shadow − disc) / (specimen − disc), areas in m² (disc 0 over a pin): 1 for a specimen
/// that stays flat, 0 for one hanging straight down. Throws std::invalid_argument when an area
/// is negative or not finite, or the specimen is not larger than the disc.
double drape_coefficient(double shadow_area_m2, double specimen_area_m2, double disc_area_m2);

}  // namespace fabform
