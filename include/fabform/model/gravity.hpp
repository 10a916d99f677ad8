#pragma once
// The fabric's weight (seeds 000 and 004; seed 003 has none), a term of the model: each node
// carries the weight of the fabric it stands for, a constant load along −z, whose potential
// −Σ f·x is what the loads do work against.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

/// Standard gravity (m/s²), the default of a scene's [gravity].
constexpr double kStandardGravity_m_s2 = 9.80665;
/// A gram-force in newtons, by definition: KES-FB's unit of force (2HB in gf·cm/cm = gf).
constexpr double kNewtonsPerGramForce = kStandardGravity_m_s2 * 1e-3;
/// KES-FB's force per width, gf/cm (2HG, and G per degree), in N/m.
constexpr double kGramForcePerCentimetre_N_m = kNewtonsPerGramForce / 0.01;

/// The weight of each node, along −z: areal density × the node's area × g.
std::vector<Eigen::Vector3d> gravity_loads(const Fabric& grid, double areal_density_kg_m2,
                                           double acceleration_m_s2);

class Gravity final : public Term {
 public:
  Gravity(const Fabric& fabric, double areal_density_kg_m2, double acceleration_m_s2);

  /// One load per node (N).
  const std::vector<Eigen::Vector3d>& loads() const { return loads_; }

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  /// −Σ f_k · x_k (J).
  double energy(const Model& model, const Positions& x) const override;
  /// −Σ f_k · (to_k − from_k), from the moves: a difference of two absolute potentials would
  /// lose its digits to m·g·z.
  double energy_change(const Model& model, const Positions& from, double from_energy,
                       const Positions& to) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  bool external() const override { return true; }
  /// When e is not well below the lightest node's load (e ≥ 0.1 of it): a run can then stop
  /// before the weight has had its effect.
  std::string tolerance_warning(double tolerance_N) const override;

 private:
  std::vector<Eigen::Vector3d> loads_;
  double areal_density_kg_m2_;
  double acceleration_m_s2_;
};

}  // namespace fabform
