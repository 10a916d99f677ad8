#pragma once
// A tool's travel (a mold pushed up into a blank, a punch, a rotating former): a translation
// and a rotation about a pivot, made in K load steps. After step k of K the body has moved
// k/K of the translation and turned k/K of each angle (about x, then y, then z, as a placement
// turns), so a straight push advances evenly and a turn about one axis turns evenly.
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fabform {

struct ToolPath {
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();  // the whole travel
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();   // the whole turn
  Eigen::Vector3d pivot_m = Eigen::Vector3d::Zero();        // what the turn is about
  int steps = 0;                                            // K; 0: the body does not move

  bool moves() const { return steps > 0; }
  /// The body's pose after step `step` of K, relative to its placement (step 0: the identity).
  Eigen::Isometry3d pose(int step) const;
  /// The pose at `progress` load steps, 0 … K, fractional for a cut step (load_steps.hpp):
  /// progress/K of the translation and of each angle. At a whole number it is pose(int), bit
  /// for bit (the same arithmetic).
  Eigen::Isometry3d pose_at(double progress) const;
  /// The translation and the angles after step `step` (for reports).
  Eigen::Vector3d translation_at(int step) const;
  Eigen::Vector3d rotation_deg_at(int step) const;

  /// Why the path cannot be used, or ""; `field` gets the offending field's name.
  std::string invalid_reason(std::string* field = nullptr) const;
};

}  // namespace fabform
