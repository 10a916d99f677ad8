#pragma once
// What the penalties that keep the fabric's springs out of a body share (edge_contact.hpp,
// spring_contact.hpp): which springs they keep out, the length that scales their depths, their
// stiffness against the fabric's, and the penalty of a depth,
//   φ(δ) = κδ³/(6h) for 0 < δ < h, κ(δ²/2 − hδ/2 + h²/6) beyond,
// whose stiffness φ'' rises from 0 to κ over a depth h, so that Newton's matrix changes
// continuously as a spring first reaches in.
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"

namespace fabform {

struct Model;

/// Warp, weft and shear springs lie in the fabric's surface; a bending spring spans two cells.
inline bool stretches_surface(SpringKind kind) { return kind != SpringKind::bend; }

/// Calls visit(s, a, b, node_is_a) for each warp, weft and shear spring s at `node`, its ends a
/// and b where x has them but the node's, placed at `at`: a term's force on one node, or its
/// change of energy when that node alone moves, from its springs' penalties.
template <class Visit>
void for_each_surface_spring_at(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x, int node,
                                const Eigen::Vector3d& at, Visit visit) {
  for (const int s : fabric.springs_at(node)) {
    const Spring& spring = fabric.springs()[static_cast<std::size_t>(s)];
    if (!stretches_surface(spring.kind)) continue;
    const bool is_a = spring.a == node;
    visit(s, is_a ? at : x[static_cast<std::size_t>(spring.a)], is_a ? x[static_cast<std::size_t>(spring.b)] : at,
          is_a);
  }
}

/// The mean rest length of the warp and weft springs (0 for a fabric without any).
double mean_surface_spring_length(const Fabric& fabric);

/// The onset h over which a penalty's stiffness rises to κ, as a share of the mean surface spring.
constexpr double kContactOnsetShare = 0.02;
/// h for a fabric.
inline double contact_onset_m(const Fabric& fabric) { return kContactOnsetShare * mean_surface_spring_length(fabric); }

/// `ratio` × the model's softest warp or weft spring's stiffness at rest (N/m), 0 when its tables
/// start slack.
double contact_stiffness(const Model& model, double ratio);

/// φ(δ), φ'(δ) and φ''(δ) for stiffness κ (N/m) reached over onset h (m).
struct OnsetPenalty {
  double value = 0.0;
  double slope = 0.0;
  double curvature = 0.0;
};
OnsetPenalty onset_penalty(double depth_m, double stiffness_N_m, double onset_m);

}  // namespace fabform
