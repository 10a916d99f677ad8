#pragma once
// Contact of the fabric's surface with a body, along its springs. Contact is the nodes' (seed
// 003): a node is kept out of a body, but a straight spring between two nodes resting on either
// side of an edge passes through the corner. Here each warp, weft and shear spring is also kept
// out along its length, by a penalty on how deep points spread along it lie inside the body:
//   Π = Σ_i φ(δ(a + t_i (b − a))) / n,  t_i = (i + ½)/n,  i = 0 … n − 1,
// δ(p) = max(0, −signed distance of p to the body's mesh), φ(δ) = κδ³/(6h) for δ < h and
// κ(δ²/2 − hδ/2 + h²/6) beyond, κ far above the fabric's stiffness, reached over a depth h of
// 2 % of a spring so that Newton's matrix changes continuously as a spring reaches in. The
// signed distance is continuous in p, so Π is continuous wherever the springs and the body are,
// whatever the faceting: no edge is singled out, so no spring's energy jumps as its deepest
// point passes from one edge, facet or corner to the next (the plane-wedge depth of
// edge_contact.hpp jumps beside a CAD part's narrow fillet facets, where Newton stalls). Π's
// gradient turns where a sample crosses the inside's medial surface (the bisector under an
// edge), by an amount that vanishes with the depth.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/model/term.hpp"

namespace fabform {

class NearbyQueries;

/// Where a spring's sample point lies inside a body: the body, the sample's share t along a–b,
/// its depth δ and ∂δ/∂p (a unit vector into the body).
struct SampleDepth {
  int body = 0;
  double along = 0.0;
  double depth = 0.0;
  Eigen::Vector3d inward = Eigen::Vector3d::Zero();
};

class SpringContact final : public Term {
 public:
  /// Keeps the warp, weft and shear springs out of the bodies listed (indices into the model's
  /// bodies), with penalty stiffness κ (N/m). Throws std::invalid_argument for a stiffness that
  /// is not positive and finite or a body the model does not have.
  SpringContact(const Model& model, std::vector<int> bodies, double stiffness_N_m);

  /// κ for a model: 1e5 × its softest warp or weft spring's stiffness at rest, a hundred times the
  /// edge penalty's: only the few samples near a spring's deepest point push, and the depth at
  /// which they hold it falls slowly with κ (tools/bench_cad_contact.py's springs variant keeps
  /// every cut within 0.16 mm at 1e5).
  static double default_stiffness(const Model& model);

  /// How many points along a spring are kept out of the bodies.
  static constexpr int kSamples = 32;

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  void add_forces(const Model& model, const Positions& x, std::vector<Eigen::Vector3d>& forces) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  /// φ''(δ) n nᵀ per sample inside, spread to the spring's ends by (1 − t, t): the Gauss–Newton
  /// part, positive semi-definite (the distance's own curvature round an edge left out).
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  /// Refuses a step that takes a sample deeper into a body by more than the penalty's onset h at
  /// once: the step's matrix knew nothing of a body the sample had not reached, and a spring
  /// carried through a thin wall (a rib, a fin) in one step is held there, not pushed back.
  std::unique_ptr<StepCheck> step_check(const Model& model, const Positions& from) const override;
  /// What it needs of its solver; the scene reader asks the same of a scene that would have it.
  static constexpr SolverNeeds kNeeds = SolverNeed::stiff_penalty;
  SolverNeeds needs() const override { return kNeeds; }

 private:
  struct Penalty {
    double energy = 0.0;
    Eigen::Vector3d gradient_a = Eigen::Vector3d::Zero();
    Eigen::Vector3d gradient_b = Eigen::Vector3d::Zero();
  };
  /// The samples of segment a–b inside the bodies; `a_distances` and `b_distances`, when given,
  /// hold a's and b's signed distances to each listed body (else they are looked up).
  std::vector<SampleDepth> samples_inside(NearbyQueries& queries, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const double* a_distances = nullptr,
                                          const double* b_distances = nullptr) const;
  Penalty penalty(const std::vector<SampleDepth>& samples) const;
  /// Each surface spring's samples inside at x (none for a bending spring), in spring order.
  std::vector<std::vector<SampleDepth>> every_spring(const Model& model, const Positions& x) const;

  class DepthGrowth;

  std::vector<int> bodies_;
  double stiffness_N_m_;
  double onset_m_;  // the depth over which the penalty's stiffness rises to κ
};

}  // namespace fabform
