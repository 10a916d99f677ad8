#pragma once
// Where a fabric's nodes lie in the flat cloth and which faces they bound, for each shape the
// seeds use: seed 003's rectangle of n × m nodes, and seed 000's circle, meshed as the lattice
// points inside it (quadrangular; triangular is the same lattice with diagonal springs), as
// concentric rings on radial lines (arc) or as the lattice with its inner nodes moved by a seeded
// random fraction of its spacing (jittered, issue 22 item 4: a mesh with no symmetry to impose a
// fold count). The springs are derived from the faces (fabric.hpp).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/panel_spec.hpp"

namespace fabform {

/// A quadrilateral or a triangle of the flat fabric, counter-clockwise seen from +z.
struct Face {
  std::array<int, 4> corner = {-1, -1, -1, -1};
  int corners = 4;
};

// A jittered mesh's largest move, as a fraction of the spacing. With every node within r·spacing
// of its lattice point, a cell's corner stays on its side of the diagonal through its two
// neighbours (h/√2 away) while 3r < 1/√2, so every cell stays convex; 0.2 keeps each corner 0.1
// of the spacing clear of it, and each side within asin(2r) = 24° of its lattice direction, so
// that it stays a warp or a weft spring.
constexpr double kMaxJitter = 0.2;

struct FabricSpec {
  enum class Shape { rectangle, circle, panels };
  enum class Mesh { quadrangular, triangular, arc, jittered };
  // A rectangle sewn to itself across one direction: a circular knit's seamless tube, the warp
  // running round it (its left and right edges sewn) or along it (bottom and top sewn). The
  // lattice stays the rectangle's; the seam is a term of the model (seam.hpp).
  enum class Tube { none, warp_round, warp_along };
  double width_m = 0.1;   // rectangle W along warp (x); circle: its diameter (= height_m)
  double height_m = 0.1;  // rectangle H along weft (y)
  int divisions_warp = 40;  // rectangle: springs along x; circle lattice: cells across the diameter
  int divisions_weft = 40;  // rectangle: springs along y; circle lattice: as divisions_warp
  Shape shape = Shape::rectangle;
  Mesh mesh = Mesh::quadrangular;  // circles; a rectangle is quadrangular
  int rings = 0;   // arc: concentric rings around the centre node
  int spokes = 0;  // arc: radial lines, nodes on each ring
  double jitter = 0.0;           // jittered: the largest move of a node, as a fraction of the spacing
  std::uint64_t jitter_seed = 1;  // jittered: the seed of the moves ([initial] seed)
  bool shear_springs = false;  // both diagonals of every four-sided cell (implied by triangular)
  bool bend_springs = false;   // a spring over every two consecutive springs in line
  bool hinges = false;         // a bending hinge across every side two faces share
  Tube tube = Tube::none;      // a rectangle only
  // panels: a garment's panels, meshed on one lattice of this spacing (warp, weft); width_m,
  // height_m and the divisions are then the lattice's extent (panel_lattice_extent).
  std::vector<PanelSpec> panels = {};
  std::array<double, 2> panel_spacing_m = {0.01, 0.01};

  /// Why the spec cannot make a fabric, or "".
  std::string invalid_reason() const;
  double radius_m() const { return 0.5 * width_m; }
  /// Whether the nodes sit on multiples of the lattice spacing, so that cells and springs take
  /// their sizes from it exactly (not on an arc or a jittered mesh).
  bool spaced_exactly() const { return mesh == Mesh::quadrangular || mesh == Mesh::triangular; }
};

const char* to_string(FabricSpec::Shape shape);
const char* to_string(FabricSpec::Mesh mesh);
const char* to_string(FabricSpec::Tube tube);

struct FabricLayout {
  std::vector<Eigen::Vector3d> rest;           // flat positions, z = 0
  std::vector<std::array<int, 2>> lattice;     // per node: (i, j), or (ring, spoke) on an arc mesh
  std::array<int, 2> lattice_size = {0, 0};    // extents of the lattice indices
  std::array<double, 2> spacing = {0.0, 0.0};  // lattice spacing along x and y (arc: ring spacing, arc length)
  std::vector<Face> faces;
  // Nodes moved off their lattice point (onto a panel's outline); empty when none is.
  std::vector<unsigned char> moved;
  std::vector<PanelMesh> panels;
};

/// The lattice of a rectangle; the lattice cells inside a circle; an arc mesh. The spec must be
/// valid (FabricSpec::invalid_reason); a circle lattice with no cell inside throws
/// std::invalid_argument.
FabricLayout rectangle_layout(const FabricSpec& spec);
FabricLayout circle_lattice_layout(const FabricSpec& spec);
FabricLayout arc_layout(const FabricSpec& spec);
/// The circle's lattice (circle_lattice_layout) with every node that is not on its outline moved
/// by its lattice point's seeded draw, uniform in a disc of radius spec.jitter × spacing.
FabricLayout jittered_layout(const FabricSpec& spec);

/// A garment's panels on one lattice (panel_spec.hpp): each panel's outline turned so its grain
/// runs along x, the lattice cells whose centres lie inside it, its boundary nodes moved onto the
/// outline (each vertex's nearest node onto the vertex, the rest onto the nearest point of their
/// edge, in order along it); the panels side by side along x, a lattice column apart. Throws
/// std::invalid_argument naming the panel where the lattice cannot follow its outline (too
/// coarse for a narrow part or a sharp corner).
FabricLayout panel_layout(const FabricSpec& spec);
/// The lattice's extent the panels take: nodes along x and along y.
std::array<int, 2> panel_lattice_extent(const FabricSpec& spec);

/// The area of a face at positions x (m²): a quadrilateral as two triangles split at corner 0.
double face_area(const Face& face, const std::vector<Eigen::Vector3d>& x);

/// The faces as triangles, split as face_area splits them, in the faces' order.
std::vector<std::array<int, 3>> face_triangles(const std::vector<Face>& faces);

}  // namespace fabform
