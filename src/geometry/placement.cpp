#include "fabform/geometry/placement.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "fabform/angles.hpp"

namespace fabform {
namespace {


}  // namespace

Eigen::Matrix3d rotation_from_degrees(const Eigen::Vector3d& degrees) {
  const Eigen::Vector3d r = degrees * kPi / 180.0;
  return (Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

std::string Placement::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (!(std::isfinite(scale) && scale > 0.0)) return bad("scale", "must be positive and finite");
  if (!rotation_deg.allFinite()) return bad("rotation_deg", "must be finite");
  if (!translation_m.allFinite()) return bad("translation_m", "must be finite");
  return "";
}

bool parse_length_unit(const std::string& unit, double* metres_per_unit) {
  if (unit == "m") *metres_per_unit = 1.0;
  else if (unit == "cm") *metres_per_unit = 0.01;
  else if (unit == "mm") *metres_per_unit = 0.001;
  else if (unit == "in") *metres_per_unit = 0.0254;
  else return false;
  return true;
}

TriangleMesh place(const TriangleMesh& mesh, const Placement& placement) {
  const Eigen::Matrix3d rotation = rotation_from_degrees(placement.rotation_deg);
  const double factor = placement.metres_per_unit * placement.scale;
  TriangleMesh placed = mesh;
  for (auto& v : placed.vertices) v = rotation * (factor * v) + placement.translation_m;
  return placed;
}

}  // namespace fabform
