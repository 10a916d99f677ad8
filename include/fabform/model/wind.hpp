#pragma once
// Seed 004's wind: on each node F = C [n·(v_wind − v)] n, n the node's averaged normal, v its
// velocity. Only the part of the relative wind across the fabric pushes it, and a fabric moving
// with the wind feels none. C here is per area of fabric (N·s/m³), the node's force C·A_k times
// the bracket, so a region feels the same wind however finely it is meshed; seed 004's
// per-node constant is C·A_k of its grid. The force has no potential and depends on velocity:
// only `dynamic` models it. At rest (v = 0) it is a load that follows the fabric's normal,
// and that part enters every node's resultant R (model.hpp).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

struct Wind {
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  double coefficient_N_s_m3 = 0.0;  // C per area of fabric

  /// Why the wind cannot be used, or "" when it can: it needs a direction (a non-zero velocity),
  /// a speed of at most 1000 m/s (three times the speed of sound: beyond, a unit mistake) and
  /// C in (0, 1e6]. `field` gets the offending member's name as a scene spells it.
  std::string invalid_reason(std::string* field = nullptr) const;
};

/// The node's unit normal at positions x with the node at `at`: the sum of its faces' vector
/// areas (seed 004 averages its triangles' normals; weighting by area keeps a sliver from
/// tipping it), normalised. Zero where they cancel or vanish (a node folded flat on itself).
/// A quadrilateral's vector area is half the cross product of its diagonals, exact for a
/// warped one as well.
Eigen::Vector3d node_normal(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x, int node,
                            const Eigen::Vector3d& at);
inline Eigen::Vector3d node_normal(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x, int node) {
  return node_normal(fabric, x, node, x[static_cast<std::size_t>(node)]);
}

/// C·A·[n·(v_wind − v)]·n (N) on a node of area A (m²) with unit normal n moving at v.
Eigen::Vector3d wind_force(const Wind& wind, double node_area_m2, const Eigen::Vector3d& normal,
                           const Eigen::Vector3d& velocity_m_s);

/// The velocity after a step of Δt under the wind's drag −C·A·(n·v)·n alone, taken implicitly:
/// v − a/(1 + a·|n|²)·(n·v)·n with a = Δt·C·A/m (`drag_step`, ≥ 0). Unconditionally stable
/// however strong the wind, so the drag never shortens the time step; it is seed 004's explicit
/// step as Δt → 0. n is the unit normal, or its projection on the directions a held node or a
/// node on a body may move in (then v lies in them, and so does the result).
Eigen::Vector3d after_wind_drag(double drag_step, const Eigen::Vector3d& normal, const Eigen::Vector3d& velocity_m_s);

/// The wind as a term of the model: its force at rest in every node's R, its drag in each of
/// dynamic's steps. It has no potential, so only `dynamic` models it.
class WindLoad final : public Term {
 public:
  /// Throws std::invalid_argument when wind.invalid_reason() is not empty.
  explicit WindLoad(const Wind& wind);
  const Wind& wind() const { return wind_; }

  std::string describe(const Model& model) const override;
  /// C·A·(n·v_wind)·n, n the node's normal with it at `at`.
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  double energy(const Model& /*model*/, const Positions& /*x*/) const override { return 0.0; }
  double node_energy_change(const Model& /*model*/, const Positions& /*x*/, int /*node*/,
                            const Eigen::Vector3d& /*at*/) const override {
    return 0.0;
  }
  /// The drag −C·A·(n·v)·n, taken implicitly (after_wind_drag) with every node's normal at the
  /// step's start, projected on the directions the node may move in so that no reaction on a
  /// held axis leaks into a free one through (n·v)·n.
  std::unique_ptr<StepDrag> drag(const Model& model, const Positions& x) const override;
  bool external() const override { return true; }
  /// What it needs of its solver; the scene reader asks the same of a scene that would have it.
  static constexpr SolverNeeds kNeeds = SolverNeed::velocity;
  SolverNeeds needs() const override { return kNeeds; }

 private:
  Wind wind_;
};

}  // namespace fabform
