#pragma once
// The fabric: nodes in the flat, unstretched cloth, the springs between them and the faces
// they bound. Seed 003's n × m rectangle (warp along x, index i; weft along y, index j) is one
// layout; seed 000's circles meshed quadrangular, triangular (the same lattice with diagonal
// springs), arc (concentric rings on radial lines) and jittered (the lattice, its inner nodes
// moved at random) are the others. Seed 004's shear (diagonal) and bend (skip-one) springs are
// added on request.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric_layout.hpp"
#include "fabform/fabric/hinge.hpp"

namespace fabform {

/// What a spring models, which sets the table it follows: warp and weft carry the fabric's
/// measured tension, shear the bias (diagonal) response, bend the skip-one springs' resistance.
enum class SpringKind { warp, weft, shear, bend };
const char* to_string(SpringKind kind);

struct Spring {
  int a = 0;                 // the lower-numbered node
  int b = 0;
  double rest_length = 0.0;  // m
  double width = 0.0;        // m of fabric the spring stands for: its area A_k (seed 003) / L
  SpringKind kind = SpringKind::warp;
};

class Fabric {
 public:
  /// Throws std::invalid_argument when spec.invalid_reason() is not empty.
  explicit Fabric(const FabricSpec& spec);

  const FabricSpec& spec() const { return spec_; }
  int node_count() const { return static_cast<int>(rest_.size()); }
  /// Position in the flat fabric, the lower-left corner of its bounding box at the origin.
  Eigen::Vector3d rest_position(int node) const { return rest_[static_cast<std::size_t>(node)]; }
  bool on_perimeter(int node) const { return perimeter_[static_cast<std::size_t>(node)] != 0; }

  const std::vector<Spring>& springs() const { return springs_; }
  const std::vector<Face>& faces() const { return faces_; }

  /// Indices into springs() of the springs at a node.
  struct SpringIndices {
    const int* first;
    const int* last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
    int size() const { return static_cast<int>(last - first); }
  };
  SpringIndices springs_at(int node) const {
    const auto k = static_cast<std::size_t>(node);
    return {spring_ids_.data() + spring_offset_[k], spring_ids_.data() + spring_offset_[k + 1]};
  }

  /// The bending hinges (FabricSpec::hinges), and those that reach a node (indices into hinges()).
  const std::vector<Hinge>& hinges() const { return hinges_; }
  SpringIndices hinges_at(int node) const {
    const auto k = static_cast<std::size_t>(node);
    return {hinge_ids_.data() + hinge_offset_[k], hinge_ids_.data() + hinge_offset_[k + 1]};
  }

  /// The faces a node is a corner of (indices into faces()).
  SpringIndices faces_at(int node) const {
    const auto k = static_cast<std::size_t>(node);
    return {face_ids_.data() + face_offset_[k], face_ids_.data() + face_offset_[k + 1]};
  }

  /// The area of fabric each node stands for (m²): its faces' areas shared equally among
  /// their corners, so they sum to flat_area().
  const std::vector<double>& node_areas() const { return node_areas_; }
  /// The flat fabric's area (m²), the sum of its faces.
  double flat_area() const { return flat_area_; }

  /// Nodes grouped so that no spring or hinge joins two nodes of a group: the nodes of one
  /// group can move at once, independently. The checkerboard for a rectangle's warp and weft
  /// springs alone.
  const std::vector<std::vector<int>>& colours() const { return colours_; }

  /// Lattice indices: (i, j) on a rectangle or a circle's lattice, (ring, spoke) on an arc mesh
  /// (the centre is (0, 0)). node() is -1 where the lattice has no node.
  int nodes_warp() const { return lattice_size_[0]; }
  int nodes_weft() const { return lattice_size_[1]; }
  int node(int i, int j) const;
  int i_of(int node) const { return lattice_[static_cast<std::size_t>(node)][0]; }
  int j_of(int node) const { return lattice_[static_cast<std::size_t>(node)][1]; }
  /// "node (i, j)" or "node (ring r, spoke s)", for messages.
  std::string node_name(int node) const;
  /// Springs from one side of the fabric to the other: its largest lattice extent.
  int divisions_across() const;

  /// Whether a node sits on its lattice point, a multiple of the spacing (not on an arc or a
  /// jittered mesh, nor a panel's boundary node moved onto its outline).
  bool on_lattice(int node) const {
    return spec_.spaced_exactly() && (moved_.empty() || moved_[static_cast<std::size_t>(node)] == 0);
  }
  /// A garment's panels as meshed (FabricSpec::Shape::panels), else none.
  const std::vector<PanelMesh>& panels() const { return panels_; }

  /// The lattice's spacing along x and y (rectangle and circle lattices; an arc mesh's ring spacing).
  double spacing_warp() const { return spacing_[0]; }
  double spacing_weft() const { return spacing_[1]; }

 private:
  void adopt(FabricLayout layout);
  void add_edge_springs();
  void add_shear_springs();
  void add_bend_springs();
  void add_hinges();
  std::array<double, 4> bend_weights(const Hinge& hinge) const;
  void index_springs();
  void index_faces();
  void mark_perimeter();
  void colour_nodes();

  FabricSpec spec_;
  std::vector<Eigen::Vector3d> rest_;
  std::vector<std::array<int, 2>> lattice_;
  std::array<int, 2> lattice_size_ = {0, 0};
  std::vector<int> lattice_node_;  // nodes_warp × nodes_weft, -1 for none
  std::array<double, 2> spacing_ = {0.0, 0.0};
  std::vector<Face> faces_;
  std::vector<unsigned char> moved_;
  std::vector<PanelMesh> panels_;
  std::vector<double> face_areas_;  // flat, per face
  std::vector<std::size_t> face_offset_;
  std::vector<int> face_ids_;
  std::vector<double> node_areas_;
  double flat_area_ = 0.0;
  std::vector<Spring> springs_;
  std::vector<std::size_t> spring_offset_;
  std::vector<int> spring_ids_;
  std::vector<Hinge> hinges_;
  std::vector<std::size_t> hinge_offset_;
  std::vector<int> hinge_ids_;
  std::vector<unsigned char> perimeter_;
  std::vector<std::vector<int>> colours_;
};

}  // namespace fabform
