#include "fabform/analysis/cell_deformation.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "fabform/analysis/fabric_figures.hpp"
#include "fabform/angles.hpp"

namespace fabform {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The direction of a face's warp (weft) sides: their sum, each side turned to run the way the
// first one does in the flat fabric, so opposite sides add rather than cancel.
struct Directions {
  Eigen::Vector3d warp_flat = Eigen::Vector3d::Zero(), weft_flat = Eigen::Vector3d::Zero();
  Eigen::Vector3d warp_formed = Eigen::Vector3d::Zero(), weft_formed = Eigen::Vector3d::Zero();
};

Directions side_directions(const Fabric& fabric, const Face& face, const std::vector<Eigen::Vector3d>& x) {
  Directions d;
  for (int c = 0; c < face.corners; ++c) {
    const int p = face.corner[static_cast<std::size_t>(c)];
    const int q = face.corner[static_cast<std::size_t>((c + 1) % face.corners)];
    const int s = stretch_spring_between(fabric, p, q);
    if (s < 0) continue;
    const bool warp = fabric.springs()[static_cast<std::size_t>(s)].kind == SpringKind::warp;
    Eigen::Vector3d& flat = warp ? d.warp_flat : d.weft_flat;
    Eigen::Vector3d& formed = warp ? d.warp_formed : d.weft_formed;
    const Eigen::Vector3d side_flat = fabric.rest_position(q) - fabric.rest_position(p);
    const double sign = side_flat.dot(flat) < 0.0 ? -1.0 : 1.0;
    flat += sign * side_flat;
    formed += sign * (x[static_cast<std::size_t>(q)] - x[static_cast<std::size_t>(p)]);
  }
  return d;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return kDegreesPerRadian * std::atan2(a.cross(b).norm(), a.dot(b));
}

double shear_angle_deg(const Fabric& fabric, const Face& face, const std::vector<Eigen::Vector3d>& x) {
  const Directions d = side_directions(fabric, face, x);
  if (d.warp_flat.isZero() || d.weft_flat.isZero() || d.warp_formed.isZero() || d.weft_formed.isZero()) return kNaN;
  return angle_deg(d.warp_flat, d.weft_flat) - angle_deg(d.warp_formed, d.weft_formed);
}

std::vector<Eigen::Vector3d> rest_positions(const Fabric& fabric) {
  std::vector<Eigen::Vector3d> rest;
  rest.reserve(static_cast<std::size_t>(fabric.node_count()));
  for (int k = 0; k < fabric.node_count(); ++k) rest.push_back(fabric.rest_position(k));
  return rest;
}

}  // namespace

std::string CellDeformationOptions::invalid_reason() const {
  if (!(locking_angle_deg > 0.0 && locking_angle_deg < 90.0)) return "the locking angle must lie in (0, 90) degrees";
  if (!(compression_strain >= 0.0 && compression_strain < 1.0)) return "the compression strain must lie in [0, 1)";
  return "";
}

CellDeformation cell_deformation(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                 const CellDeformationOptions& options) {
  if (const std::string why = options.invalid_reason(); !why.empty()) throw std::invalid_argument(why);
  const Fabric& fabric = model.fabric;
  const std::vector<Eigen::Vector3d> rest = rest_positions(fabric);
  const std::vector<FormedCell> cells = formed_cells(model, x);
  CellDeformation d;
  for (std::size_t f = 0; f < cells.size(); ++f) {
    const Face& face = fabric.faces()[f];
    const double shear = shear_angle_deg(fabric, face, x);
    const double ratio = cells[f].area_m2 > 0.0 ? face_area(face, rest) / cells[f].area_m2 : kNaN;
    const bool locked = std::abs(shear) > options.locking_angle_deg;
    const bool compressed = cells[f].warp_strain < -options.compression_strain &&
                            cells[f].weft_strain < -options.compression_strain;
    d.shear_angle_deg.push_back(shear);
    d.thickness_ratio.push_back(ratio);
    d.wrinkle_risk.push_back(locked || compressed ? 1 : 0);
    d.wrinkle_cells += locked || compressed ? 1 : 0;
    if (std::abs(shear) > d.shear_angle_max_deg || (d.shear_angle_max_face < 0 && !std::isnan(shear)))
      d.shear_angle_max_deg = std::abs(shear), d.shear_angle_max_face = static_cast<int>(f);
    if (ratio < d.thickness_ratio_min || (d.thickness_ratio_min_face < 0 && !std::isnan(ratio)))
      d.thickness_ratio_min = ratio, d.thickness_ratio_min_face = static_cast<int>(f);
  }
  return d;
}

}  // namespace fabform
