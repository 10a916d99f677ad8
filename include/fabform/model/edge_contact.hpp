#pragma once
// Contact of the fabric's surface with a body's convex edges. Contact is the nodes' (seed 003): a
// node is kept out of a body, but a straight spring between two nodes resting on the two faces of
// a sharp edge passes under it, through the corner. Here each warp, weft and shear spring is also
// kept out of the wedge under every convex edge sharper than a body's `edge_contact_deg`, by a
// penalty on how deep it reaches into the wedge:
//   Π = w φ(δ),  φ(δ) = κδ³/(6h) for 0 < δ < h, κ(δ²/2 − hδ/2 + h²/6) beyond,
// δ the depth below the edge's two faces of the point where the spring crosses the wedge's
// bisecting plane (the deepest point of a straight segment in a wedge; seed 003's cut), w a weight
// that is 1 along the edge and falls smoothly to 0 within a margin past an end the body goes on
// past (so that the energy is C¹ where a spring leaves one edge for the next), κ a stiffness far
// above the fabric's, reached over a depth h of 2 % of a spring, so that Newton's matrix changes
// continuously as a spring reaches under. Unlike a spring wrapped over an edge (edge_wrap.hpp),
// whose path jumps from edge to edge, Π changes continuously as a spring slides along and off an
// edge, so Newton converges on faceted CAD punches. It is not smooth everywhere: its gradient
// jumps where a corner's cap takes over from the wedge, and Π itself jumps at the cut-off a
// spring's length from the edge and where the crossing reaches a spring's end at a node that lies
// in a wedge but outside the body (beside a rounded corner, whose narrow facets end long before
// their planes): vacuum-formed dies stall there (docs/forming.md, "Forming over a CAD part").
// A spring that reaches in by δ > h pushes out with κ w (δ − h/2): κ is
// 1000 times the softest spring's stiffness at rest, so a 3 mm spring 0.1 mm under pushes out
// with what 23 springs carry at 100 % strain.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/geometry/edge_wrap.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

class RigidBody;

/// How a segment a–b reaches under a convex edge, in the edge's frame.
struct EdgeReach {
  double depth = 0.0;    // δ: how far below both faces it reaches (> 0)
  double along = 0.0;    // s ∈ (0, 1): where along a–b that is
  double weight = 0.0;   // w ∈ (0, 1]
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // g: ∂δ/∂a = −(1 − s) g, ∂δ/∂b = −s g
  Eigen::Vector3d weight_gradient_a = Eigen::Vector3d::Zero();  // ∂w/∂a
  Eigen::Vector3d weight_gradient_b = Eigen::Vector3d::Zero();  // ∂w/∂b
};

/// How an edge ends. At a corner (a box's) the body ends across it: a segment reaches under the
/// edge no deeper than its crossing lies from the end, and past the end not at all. Where the
/// body goes on past the end (a long CAD edge cut in pieces, a fillet's facets, a pocket's rim
/// round its corner), the wedge reaches on past it, its weight falling to 0 within `margin_m`.
struct EdgeEnds {
  bool capped_from = true;
  bool capped_to = true;
  double margin_m = 0.0;
};

/// The reach of segment a–b under `edge` (its faces' normals outward), or none when it stays
/// out of the wedge, crosses the bisecting plane outside (0, 1), runs along it, or crosses it
/// past the edge's ends (ends say how far) or farther from the edge than a–b is long.
std::optional<EdgeReach> reach_under_edge(const SharpEdge& edge, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const EdgeEnds& ends);

/// w φ(δ) of a reach (h = onset_m), its gradient with respect to a and b, and w φ''(δ).
struct EdgePenalty {
  double energy = 0.0;
  double curvature = 0.0;  // w φ''(δ)
  Eigen::Vector3d gradient_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d gradient_b = Eigen::Vector3d::Zero();
};
EdgePenalty edge_penalty(const EdgeReach& reach, double stiffness_N_m, double onset_m);

class EdgeContact final : public Term {
 public:
  /// Keeps the fabric's warp, weft and shear springs out from under the convex edges of body b
  /// sharper than angles_deg[b] (0: none of that body's), with penalty stiffness κ (N/m).
  /// Throws std::invalid_argument for a stiffness that is not positive and finite.
  EdgeContact(const Model& model, const std::vector<double>& angles_deg, double stiffness_N_m);
  ~EdgeContact() override;

  /// κ for a model: 1000 × its softest warp or weft spring's stiffness at rest.
  static double default_stiffness(const Model& model);

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  /// w φ''(δ) J Jᵀ per reach, J = ∂δ/∂(a, b): the Gauss–Newton part, positive semi-definite.
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  /// What it needs of its solver; the scene reader asks the same of a scene that would have it.
  static constexpr SolverNeeds kNeeds = SolverNeed::stiff_penalty;
  SolverNeeds needs() const override { return kNeeds; }

  /// How many edges the springs are kept from.
  int edge_count() const;

 private:
  struct BodyEdges;
  struct SpringPenalty {
    double energy = 0.0;
    Eigen::Vector3d gradient_a = Eigen::Vector3d::Zero();
    Eigen::Vector3d gradient_b = Eigen::Vector3d::Zero();
  };
  // The edges spring `spring` between pa and pb (in the body's placed frame) may reach under;
  // `refresh` looks them up anew and keeps them (edge_contact.cpp).
  struct NearEdges {
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    double slack = 0.0;
    bool valid = false;
    std::vector<int> edges;
  };
  const std::vector<int>& edges_near(const BodyEdges& body, int spring, const Eigen::Vector3d& pa,
                                     const Eigen::Vector3d& pb, bool refresh, std::vector<int>& fresh) const;
  /// The penalty of spring `spring` placed between a and b; `reaches` gets its reaches, and then
  /// its nearby edges are looked up anew.
  SpringPenalty spring_penalty(const Model& model, int spring, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               std::vector<EdgeReach>* reaches = nullptr) const;

  std::vector<BodyEdges> bodies_;
  double stiffness_N_m_;
  double margin_m_;  // how far beyond an edge's ends its weight falls to 0
  double onset_m_;   // the depth over which the penalty's stiffness rises to κ
};

}  // namespace fabform
