#include "fabform/geometry/tool_path.hpp"

#include <cmath>

#include "fabform/geometry/placement.hpp"

namespace fabform {

Eigen::Vector3d ToolPath::translation_at(int step) const {
  return translation_m * (static_cast<double>(step) / steps);
}

Eigen::Vector3d ToolPath::rotation_deg_at(int step) const {
  return rotation_deg * (static_cast<double>(step) / steps);
}

Eigen::Isometry3d ToolPath::pose(int step) const { return pose_at(static_cast<double>(step)); }

// translation_at and rotation_deg_at's arithmetic, so that a whole progress gives pose(int)'s bits.
Eigen::Isometry3d ToolPath::pose_at(double progress) const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (progress == 0.0 || !moves()) return pose;
  const double part = progress / steps;
  const Eigen::Vector3d moved = translation_m * part;
  const Eigen::Vector3d turned = rotation_deg * part;
  const Eigen::Matrix3d turn = rotation_from_degrees(turned);
  pose.linear() = turn;
  pose.translation() = pivot_m - turn * pivot_m + moved;
  return pose;
}

std::string ToolPath::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (!(steps >= 1 && steps <= 100000)) return bad("steps", "must be between 1 and 100000");
  if (!translation_m.allFinite()) return bad("translation_m", "must be finite");
  if (!rotation_deg.allFinite()) return bad("rotation_deg", "must be finite");
  if (!pivot_m.allFinite()) return bad("pivot_m", "must be finite");
  if (translation_m.isZero(0.0) && rotation_deg.isZero(0.0))
    return bad("translation_m", "a path that neither moves nor turns the body: give translation_m or rotation_deg");
  return "";
}

}  // namespace fabform
