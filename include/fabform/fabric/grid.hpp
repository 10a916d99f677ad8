#pragma once
// The fabric of seed 003: an n × m grid of nodes over a W × H rectangle, warp along x
// (index i), weft along y (index j), joined by warp and weft springs.
#include <array>
#include <vector>

#include <Eigen/Core>

namespace fabform {

enum class Direction { warp, weft };

struct Spring {
  int a = 0;                 // node at the lower index end
  int b = 0;                 // node at the upper index end
  double rest_length = 0.0;  // m
  double width = 0.0;        // m of fabric the spring stands for (seed 003, Figure 3)
  Direction direction = Direction::warp;
};

struct GridSpec {
  double width_m = 0.1;   // W, along warp (x)
  double height_m = 0.1;  // H, along weft (y)
  int divisions_warp = 40;
  int divisions_weft = 40;
};

class FabricGrid {
 public:
  /// Throws std::invalid_argument for non-positive sizes or divisions.
  explicit FabricGrid(const GridSpec& spec);

  int nodes_warp() const { return n_; }  // n, nodes along x
  int nodes_weft() const { return m_; }  // m, nodes along y
  int node_count() const { return n_ * m_; }
  int node(int i, int j) const { return j * n_ + i; }
  int i_of(int node) const { return node % n_; }
  int j_of(int node) const { return node / n_; }
  bool on_perimeter(int node) const;

  double spacing_warp() const { return spec_.width_m / (n_ - 1); }
  double spacing_weft() const { return spec_.height_m / (m_ - 1); }
  const GridSpec& spec() const { return spec_; }

  /// Position of a node in the flat, unstretched fabric, the lower-left corner at the origin.
  Eigen::Vector3d rest_position(int node) const;

  const std::vector<Spring>& springs() const { return springs_; }
  /// The area of fabric each node stands for (m²): a quarter of w·L of every spring at it, so
  /// an inner node carries one cell and the areas sum to W·H (each direction tiles it once).
  std::vector<double> node_areas() const;

  /// Indices into springs() of the (up to four) springs at a node; -1 where there is none.
  const std::array<int, 4>& springs_at(int node) const { return springs_at_[node]; }

 private:
  void add_spring(int a, int b, double rest_length, double width, Direction direction);

  GridSpec spec_;
  int n_ = 0;
  int m_ = 0;
  std::vector<Spring> springs_;
  std::vector<std::array<int, 4>> springs_at_;
};

}  // namespace fabform
