#pragma once
// Seed 003's convergence measure (§3.3): V_k = |R| for a free node and |R*|, the part of R
// tangent to the body, for a node in contact whose R presses into the body; locked axes carry
// no residual. measure_equilibrium recomputes it from positions alone (contact found by
// geometry, not taken from any solver's bookkeeping), so a test can check a solver's claim.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fabform/geometry/nearby_queries.hpp"
#include "fabform/model/model.hpp"
#include "fabform/model/spring_cuts.hpp"

namespace fabform {

/// The unbalanced force at a node: R with locked axes removed, and for a node in contact
/// (normal != nullptr) whose R presses into the body, its part R* along the directions the
/// node may still move in: free axes within the tangent plane. With Coulomb friction μ
/// (`friction`), the body also holds up to μ·λ of R*, λ = pressing_force (below): what stays
/// is R*'s excess over the friction cone, so a node inside the cone is balanced, stuck or not.
///
/// A free node resting in a valley of the body (`crease`: its second face's normal, the first
/// being `contact_normal`; rigid_body.hpp's valley_normals) is held by both faces while R presses
/// into both: R = a n₁ + b n₂ + γ t with a, b ≤ 0 (t along the crease), and only γ t is
/// unbalanced, less what friction holds of it, μ·|a n₁ + b n₂|. Where R pulls off one face it
/// rests on the other alone (the one-normal rule above), and where it pulls off both it is free.
/// A node held on some axis ignores the crease.
Eigen::Vector3d unbalanced_force(const Eigen::Vector3d& resultant, AxisMask locks,
                                 const Eigen::Vector3d* contact_normal, double friction = 0.0,
                                 const Eigen::Vector3d* crease = nullptr);

/// λ, the force with which R presses a node on a body of unit normal n (0 when R pulls it off):
/// the body's reaction along n that keeps the node's free axes on the tangent plane. Locks take
/// the rest of R, so for a node held on some axes λ = −R_free·n_free / |n_free|² (n_free: n
/// with the held axes removed); a node held on every axis the body cannot be pressing on. On a
/// crease (as above) held by both faces, |a n₁ + b n₂|.
double pressing_force(const Eigen::Vector3d& resultant, AxisMask locks, const Eigen::Vector3d& normal,
                      const Eigen::Vector3d* crease = nullptr);

/// Which faces of a crease hold a free node whose resultant is R (unbalanced_force above): both,
/// the first (normal n₁) or the second (n₂) alone, or none (R pulls off both).
enum class CreaseHold { both, first, second, none };
CreaseHold crease_hold(const Eigen::Vector3d& resultant, const Eigen::Vector3d& first, const Eigen::Vector3d& second);

/// The body surface nearest to p, and which body it is (-1 for a model without bodies).
struct NearestSurface {
  SurfacePoint point;
  int body = -1;
};
/// `queries` serves the model's bodies, and is cheapest asked about neighbouring points in turn.
NearestSurface nearest_surface(const Model& model, NearbyQueries& queries, const Eigen::Vector3d& p);

/// The normals with which a body holds a node touching it at `nearest` (whose body is >= 0):
/// the nearest point's normal, or in a valley, for a node held on no axis, its two faces'
/// (unbalanced_force's contact_normal and crease).
struct SurfaceSupport {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  std::optional<Eigen::Vector3d> crease;
  const Eigen::Vector3d* crease_normal() const { return crease ? &*crease : nullptr; }
};
SurfaceSupport surface_support(const Model& model, const NearestSurface& nearest, AxisMask locks);

struct EquilibriumReport {
  std::vector<double> residual_N;      // V_k per node
  std::vector<unsigned char> contact;  // 1 where the node lies on a body
  double max_residual_N = 0.0;         // ‖V‖∞
  int worst_node = -1;
  int contact_nodes = 0;
  int sliding_nodes = 0;  // pressed on a body, R* at μ·λ (within e): it slides or is about to; μ = 0 slides
  int stuck_nodes = 0;    // pressed on a body, R* inside the cone by more than e: friction holds it
  double max_penetration_m = 0.0;      // deepest node in a body; below 0: the closest one's clearance; −∞: no body
  SpringCuts spring_cuts;              // springs reaching into a body between their nodes
};

/// A node within `contact_tolerance_m` of a body's surface counts as in contact; one whose R*
/// falls short of μ·λ by more than `tolerance_N` is stuck.
EquilibriumReport measure_equilibrium(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                      double contact_tolerance_m, double tolerance_N = 0.0);

}  // namespace fabform
