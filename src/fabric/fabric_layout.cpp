#include "fabform/fabric/fabric_layout.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "fabform/angles.hpp"

namespace fabform {
namespace {

constexpr long long kMaxNodes = 50'000'000LL;

std::string size_reason(const FabricSpec& spec) {
  if (!(std::isfinite(spec.width_m) && spec.width_m > 0.0) ||
      !(std::isfinite(spec.height_m) && spec.height_m > 0.0))
    return "fabric size must be positive and finite";
  return "";
}

std::string rectangle_reason(const FabricSpec& spec) {
  if (spec.mesh != FabricSpec::Mesh::quadrangular)
    return "a rectangle is meshed quadrangular (diagonal springs come with shear)";
  if (spec.divisions_warp < 1 || spec.divisions_weft < 1) return "fabric divisions must be at least 1";
  if ((spec.divisions_warp + 1LL) * (spec.divisions_weft + 1LL) > kMaxNodes)
    return "fabric has more than 50 million nodes";
  const int round = spec.tube == FabricSpec::Tube::warp_round ? spec.divisions_warp : spec.divisions_weft;
  if (spec.tube != FabricSpec::Tube::none && round < 3) return "a tube needs at least 3 divisions round it";
  return "";
}

std::string circle_reason(const FabricSpec& spec) {
  if (spec.tube != FabricSpec::Tube::none) return "a tube is a rectangle sewn to itself, not a circle";
  if (spec.width_m != spec.height_m) return "a circle's width and height are its diameter";
  if (spec.mesh == FabricSpec::Mesh::arc) {
    if (spec.rings < 1) return "an arc mesh needs at least 1 ring";
    if (spec.spokes < 3) return "an arc mesh needs at least 3 spokes";
    if (1LL + static_cast<long long>(spec.rings) * spec.spokes > kMaxNodes)
      return "fabric has more than 50 million nodes";
    return "";
  }
  if (spec.mesh == FabricSpec::Mesh::jittered && !(spec.jitter > 0.0 && spec.jitter <= kMaxJitter))
    return "a jittered mesh moves its nodes by a fraction of the spacing in (0, 0.2]";
  if (spec.divisions_warp != spec.divisions_weft)
    return "a circle's lattice has as many divisions along warp as along weft";
  if (spec.divisions_warp < 3) return "a circle's lattice needs at least 3 divisions across it";
  if ((spec.divisions_warp + 1LL) * (spec.divisions_warp + 1LL) > kMaxNodes)
    return "fabric has more than 50 million nodes";
  return "";
}

std::string panels_reason(const FabricSpec& spec) {
  if (spec.panels.empty()) return "a garment needs at least one panel";
  if (spec.mesh != FabricSpec::Mesh::quadrangular) return "panels are meshed quadrangular";
  if (spec.tube != FabricSpec::Tube::none) return "a tube is a rectangle sewn to itself, not panels";
  for (const double h : spec.panel_spacing_m)
    if (!(std::isfinite(h) && h > 0.0)) return "the panels' lattice spacing must be positive and finite";
  for (const PanelSpec& panel : spec.panels)
    if (const std::string why = panel.outline.invalid_reason(); !why.empty()) return "panel '" + panel.name + "': " + why;
  const std::array<int, 2> extent = panel_lattice_extent(spec);
  if (static_cast<long long>(extent[0]) * extent[1] > kMaxNodes) return "fabric has more than 50 million nodes";
  return "";
}

}  // namespace

std::string FabricSpec::invalid_reason() const {
  if (shape == Shape::panels) return panels_reason(*this);
  if (std::string why = size_reason(*this); !why.empty()) return why;
  return shape == Shape::rectangle ? rectangle_reason(*this) : circle_reason(*this);
}

const char* to_string(FabricSpec::Shape shape) {
  switch (shape) {
    case FabricSpec::Shape::rectangle: return "rectangle";
    case FabricSpec::Shape::circle: return "circle";
    case FabricSpec::Shape::panels: return "panels";
  }
  return "?";
}

const char* to_string(FabricSpec::Tube tube) {
  switch (tube) {
    case FabricSpec::Tube::none: return "none";
    case FabricSpec::Tube::warp_round: return "warp round";
    case FabricSpec::Tube::warp_along: return "warp along";
  }
  return "?";
}

const char* to_string(FabricSpec::Mesh mesh) {
  switch (mesh) {
    case FabricSpec::Mesh::quadrangular: return "quadrangular";
    case FabricSpec::Mesh::triangular: return "triangular";
    case FabricSpec::Mesh::arc: return "arc";
    case FabricSpec::Mesh::jittered: return "jittered";
  }
  return "?";
}

double face_area(const Face& face, const std::vector<Eigen::Vector3d>& x) {
  const auto at = [&](int c) { return x[static_cast<std::size_t>(face.corner[static_cast<std::size_t>(c)])]; };
  double twice = (at(1) - at(0)).cross(at(2) - at(0)).norm();
  if (face.corners == 4) twice += (at(2) - at(0)).cross(at(3) - at(0)).norm();
  return 0.5 * twice;
}

std::vector<std::array<int, 3>> face_triangles(const std::vector<Face>& faces) {
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(2 * faces.size());
  for (const Face& f : faces) {
    triangles.push_back({f.corner[0], f.corner[1], f.corner[2]});
    if (f.corners == 4) triangles.push_back({f.corner[0], f.corner[2], f.corner[3]});
  }
  return triangles;
}

FabricLayout rectangle_layout(const FabricSpec& spec) {
  const int n = spec.divisions_warp + 1, m = spec.divisions_weft + 1;
  FabricLayout layout;
  layout.lattice_size = {n, m};
  layout.spacing = {spec.width_m / spec.divisions_warp, spec.height_m / spec.divisions_weft};
  layout.rest.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(m));
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      layout.rest.emplace_back(i * layout.spacing[0], j * layout.spacing[1], 0.0);
      layout.lattice.push_back({i, j});
    }
  for (int j = 0; j + 1 < m; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int k = j * n + i;
      layout.faces.push_back({{k, k + 1, k + 1 + n, k + n}, 4});
    }
  return layout;
}

// Seed 000: "we only use the rectangular lattice points which fall inside of the
// circumference". A lattice cell belongs to the fabric when its four corners do, so every node
// is the corner of a cell and every spring the side of one.
FabricLayout circle_lattice_layout(const FabricSpec& spec) {
  const int d = spec.divisions_warp, n = d + 1;
  const double spacing = spec.width_m / d, r = spec.radius_m();
  const auto inside = [&](int i, int j) {
    return std::hypot(i * spacing - r, j * spacing - r) <= r * (1.0 + 1e-12);
  };
  std::vector<char> used(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
  const auto at = [&](int i, int j) { return static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i); };
  for (int j = 0; j < d; ++j)
    for (int i = 0; i < d; ++i)
      if (inside(i, j) && inside(i + 1, j) && inside(i + 1, j + 1) && inside(i, j + 1))
        used[at(i, j)] = used[at(i + 1, j)] = used[at(i + 1, j + 1)] = used[at(i, j + 1)] = 1;
  FabricLayout layout;
  layout.lattice_size = {n, n};
  layout.spacing = {spacing, spacing};
  std::vector<int> node(used.size(), -1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (used[at(i, j)]) {
        node[at(i, j)] = static_cast<int>(layout.rest.size());
        layout.rest.emplace_back(i * spacing, j * spacing, 0.0);
        layout.lattice.push_back({i, j});
      }
  for (int j = 0; j < d; ++j)
    for (int i = 0; i < d; ++i) {
      const std::array<int, 4> c = {node[at(i, j)], node[at(i + 1, j)], node[at(i + 1, j + 1)], node[at(i, j + 1)]};
      if (c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[3] >= 0) layout.faces.push_back({c, 4});  // corners inside
    }
  if (layout.faces.empty())
    throw std::invalid_argument("no lattice cell lies inside the circle: use more divisions");
  return layout;
}

// Seed 000's arc mesh: rings of radius r·R/c (r = 1…c) with the same number of nodes on each,
// on straight radial lines from the centre node; quadrilaterals between rings, triangles round
// the centre (corner 0 the centre, where the two radial sides meet).
FabricLayout arc_layout(const FabricSpec& spec) {
  const int c = spec.rings, p = spec.spokes;
  const double radius = spec.radius_m();
  FabricLayout layout;
  layout.lattice_size = {c + 1, p};
  layout.spacing = {radius / c, 2.0 * kPi * radius / p};
  layout.rest.emplace_back(radius, radius, 0.0);
  layout.lattice.push_back({0, 0});
  for (int ring = 1; ring <= c; ++ring)
    for (int spoke = 0; spoke < p; ++spoke) {
      const double angle = 2.0 * kPi * spoke / p, at = radius * ring / c;
      layout.rest.emplace_back(radius + at * std::cos(angle), radius + at * std::sin(angle), 0.0);
      layout.lattice.push_back({ring, spoke});
    }
  const auto node = [&](int ring, int spoke) { return ring == 0 ? 0 : 1 + (ring - 1) * p + (spoke % p); };
  for (int spoke = 0; spoke < p; ++spoke) layout.faces.push_back({{0, node(1, spoke), node(1, spoke + 1), -1}, 3});
  for (int ring = 1; ring < c; ++ring)
    for (int spoke = 0; spoke < p; ++spoke)
      layout.faces.push_back(
          {{node(ring, spoke), node(ring + 1, spoke), node(ring + 1, spoke + 1), node(ring, spoke + 1)}, 4});
  return layout;
}

}  // namespace fabform
