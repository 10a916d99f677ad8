#pragma once
// Fabric–fabric contact, a term of the model: the cloth has a thickness d, and a node closer than
// d to a triangle of the fabric that is not its own neighbourhood is pushed off it by a smooth
// penalty on δ, its distance to the triangle's closest point,
//   ψ(δ) = κ (d − δ)³ / (3 d)   for δ < d, else 0,
// C² at δ = d, so Newton's steps and the line search see a smooth energy (in the manner of
// incremental-potential contact, which uses a log barrier: the penalty keeps the force finite,
// κ·d at δ = 0, which its stiffness makes far above what presses two plies together). κ is
// kSelfContactRatio times the fabric's steepest tension slope. Newton gets the Gauss–Newton block
// ψ''(δ) c cᵀ ⊗ n nᵀ (c = (1, −w₀, −w₁, −w₂), w the closest point's barycentric weights, n the
// unit direction from it to the node), positive semi-definite; the curvature of δ is left out.
// Each quadrilateral face is two triangles split at its corner 0. A node does not meet the
// triangles of its own faces' nodes (its one-ring and theirs), and nodes sewn node for node count
// as one (seam.hpp). Pairs are found by binning the nodes in cubes (point_grid.hpp) at every
// evaluation, O(nodes). Point–triangle pairs only: edge–edge crossings between coarse cells are
// not seen (the independent check, analysis/self_intersections.hpp, counts what crosses).
#include <array>
#include <string>
#include <vector>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

constexpr double kSelfContactRatio = 1000.0;
constexpr double kDefaultThickness_m = 0.5e-3;

/// A node closer than the thickness to a triangle: where, and how far.
struct ProximityPair {
  int node = 0;
  int triangle = 0;
  std::array<double, 3> weights{};  // of the closest point on the triangle's corners
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit, from the closest point to the node
  double distance_m = 0.0;
};

class SelfContact final : public Term {
 public:
  /// `sewn`: each node's representative (sewn_representatives); `stiffness_N_m`: κ (> 0).
  SelfContact(const Fabric& fabric, const std::vector<int>& sewn, double thickness_m, double stiffness_N_m);

  double thickness_m() const { return thickness_; }
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  /// Every node–triangle pair closer than `reach_m` at x (the thickness when 0), in order of node
  /// then triangle.
  std::vector<ProximityPair> pairs(const Positions& x, double reach_m = 0.0) const;

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const override;
  void add_forces(const Model& model, const Positions& x, std::vector<Eigen::Vector3d>& forces) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const override;
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  /// What it needs of its solver; the scene reader asks the same of a scene that would have it.
  static constexpr SolverNeeds kNeeds = SolverNeed::stiff_penalty;
  SolverNeeds needs() const override { return kNeeds; }

 private:
  bool excluded(int node, int triangle) const;
  double penalty(double distance) const;
  double penalty_slope(double distance) const;
  double penalty_curvature(double distance) const;
  // The pairs in which `node` takes part (as the point or a corner), with it moved to `at`.
  std::vector<ProximityPair> pairs_of(const Positions& x, int node) const;

  std::vector<std::array<int, 3>> triangles_;
  std::vector<int> sewn_;
  std::vector<std::vector<int>> ring_;  // per representative: the representatives it does not meet, sorted
  double thickness_;
  double stiffness_;
};

/// κ for a model: kSelfContactRatio × the steepest slope of its warp and weft tables (N/m).
double self_contact_stiffness_N_m(const Model& model);

}  // namespace fabform
