#include "fabform/fabric/initial_shape.hpp"

#include <cmath>

#include "fabform/angles.hpp"

namespace fabform {
namespace {


Eigen::Vector3d wrapped(const Fabric& grid, int node, const Eigen::Vector3d& origin,
                        const InitialShape& shape) {
  const Eigen::Vector3d flat = grid.rest_position(node);
  const double fraction = flat.x() / grid.spec().width_m - 0.5;
  const double angle = (shape.facing_deg + shape.span_deg * fraction) * kPi / 180.0;
  return {shape.axis_xy_m.x() + shape.radius_m * std::cos(angle),
          shape.axis_xy_m.y() + shape.radius_m * std::sin(angle), origin.z() + flat.y()};
}

// A tube's round direction once round the axis, from its seam at facing_deg.
Eigen::Vector3d round_tube(const Fabric& grid, int node, const Eigen::Vector3d& origin, const InitialShape& shape) {
  const Eigen::Vector3d flat = grid.rest_position(node);
  const bool warp_round = grid.spec().tube == FabricSpec::Tube::warp_round;
  const double fraction = warp_round ? flat.x() / grid.spec().width_m : flat.y() / grid.spec().height_m;
  const double angle = (shape.facing_deg + 360.0 * fraction) * kPi / 180.0;
  return {shape.axis_xy_m.x() + shape.radius_m * std::cos(angle), shape.axis_xy_m.y() + shape.radius_m * std::sin(angle),
          origin.z() + (warp_round ? flat.y() : flat.x())};
}

// The part beyond the fold line mirrored back over the part before it, height_m up.
Eigen::Vector3d folded(const Fabric& grid, int node, const Eigen::Vector3d& origin, const InitialShape& shape) {
  Eigen::Vector3d flat = grid.rest_position(node);
  if (flat.x() > shape.fold_at_m) flat.x() = 2.0 * shape.fold_at_m - flat.x(), flat.z() = shape.height_m;
  return origin + flat;
}

double lift_of(const Fabric& grid, int node, const InitialShape& shape) {
  const Eigen::Vector3d flat = grid.rest_position(node);
  switch (shape.kind) {
    case InitialShape::Kind::lift: return grid.on_perimeter(node) ? 0.0 : shape.height_m;
    case InitialShape::Kind::bump:
      return shape.height_m * std::sin(kPi * flat.x() / grid.spec().width_m) *
             std::sin(kPi * flat.y() / grid.spec().height_m);
    default: return 0.0;
  }
}

}  // namespace

std::string InitialShape::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (!std::isfinite(height_m)) return bad("height_m", "must be finite");
  if ((kind == Kind::lift || kind == Kind::bump || kind == Kind::fold) && height_m == 0.0)
    return bad("height_m", "must not be zero");
  if (!axis_xy_m.allFinite()) return bad("axis_m", "must be finite");
  if (kind == Kind::fold && !(std::isfinite(fold_at_m) && fold_at_m > 0.0)) return bad("fold_at_m", "must be positive");
  if (!std::isfinite(facing_deg)) return bad("facing_deg", "must be finite");
  if ((kind == Kind::wrap || kind == Kind::tube) && !(std::isfinite(radius_m) && radius_m > 0.0))
    return bad("radius_m", "must be positive");
  if (kind == Kind::wrap && !(span_deg > 0.0 && span_deg < 360.0))
    return bad("span_deg", "must be in (0, 360)");
  return "";
}

bool parse_initial_kind(const std::string& name, InitialShape::Kind* kind) {
  using Kind = InitialShape::Kind;
  if (name == "flat") *kind = Kind::flat;
  else if (name == "lift") *kind = Kind::lift;
  else if (name == "bump") *kind = Kind::bump;
  else if (name == "wrap") *kind = Kind::wrap;
  else if (name == "tube") *kind = Kind::tube;
  else if (name == "fold") *kind = Kind::fold;
  else if (name == "pattern") *kind = Kind::pattern;
  else return false;
  return true;
}

std::vector<Eigen::Vector3d> initial_positions(const Fabric& grid,
                                               const Eigen::Vector3d& origin,
                                               const InitialShape& shape) {
  std::vector<Eigen::Vector3d> positions(static_cast<std::size_t>(grid.node_count()));
  if (shape.kind == InitialShape::Kind::pattern) {
    for (std::size_t p = 0; p < grid.panels().size(); ++p) {
      const PanelMesh& mesh = grid.panels()[p];
      for (int k = mesh.first_node; k < mesh.first_node + mesh.node_count; ++k)
        positions[static_cast<std::size_t>(k)] = origin + placed_point(grid.spec().panels[p], mesh.plane_point(grid.rest_position(k)));
    }
    return positions;
  }
  for (int k = 0; k < grid.node_count(); ++k) {
    auto& x = positions[static_cast<std::size_t>(k)];
    if (shape.kind == InitialShape::Kind::wrap) {
      x = wrapped(grid, k, origin, shape);
    } else if (shape.kind == InitialShape::Kind::tube) {
      x = round_tube(grid, k, origin, shape);
    } else if (shape.kind == InitialShape::Kind::fold) {
      x = folded(grid, k, origin, shape);
    } else {
      x = origin + grid.rest_position(k);
      x.z() += lift_of(grid, k, shape);
    }
  }
  return positions;
}

}  // namespace fabform
