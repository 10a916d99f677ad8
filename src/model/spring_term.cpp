#include "fabform/model/spring_term.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdio>
#include <optional>

#include "fabform/fabric/spring.hpp"
#include "fabform/model/model.hpp"
#include "fabform/model/spring_energy.hpp"
#include "fabform/model/spring_path.hpp"
#include "fabform/model/wrapped_spring.hpp"
#include "fabform/thread_count.hpp"
#include "model/sum_in_index_order.hpp"

namespace fabform {
namespace {

// What a table gives in compression, said after its description ("" when it is slack there).
std::string compression_said(const TensionTable& table) {
  switch (table.compression()) {
    case Compression::none: return "";
    case Compression::linear: return ", in compression their first slope continued (fabric.compression = linear)";
    case Compression::buckling:
      return ", in compression their first slope up to Euler's buckling load pi^2 B / L^2, then the elastica's "
             "post-buckling branch (fabric.compression = buckling)";
  }
  return "";
}

const Eigen::Vector3d& at_index(const Positions& x, int node) { return x[static_cast<std::size_t>(node)]; }

}  // namespace

bool SpringTerm::covers(SpringKind kind) const {
  switch (role_) {
    case Role::stretch: return kind == SpringKind::warp || kind == SpringKind::weft;
    case Role::shear: return kind == SpringKind::shear;
    case Role::bend: return kind == SpringKind::bend;
  }
  return false;
}

std::string SpringTerm::describe(const Model& model) const {
  const Fabric& fabric = model.fabric;
  switch (role_) {
    case Role::stretch: {
      const FabricSpec::Shape shape = fabric.spec().shape;
      const std::string outline = shape == FabricSpec::Shape::rectangle ? "rectangle"
                                  : shape == FabricSpec::Shape::panels
                                      ? std::to_string(fabric.panels().size()) + " panel(s) cut along their grain"
                                      : "circle meshed " + std::string(to_string(fabric.spec().mesh));
      return "stretch: warp and weft springs of a " + outline + " of " + std::to_string(fabric.node_count()) +
             " nodes, tension-only piecewise-linear tables" + compression_said(model.warp);
    }
    case Role::shear:
      return "shear: diagonal springs (rest length the cell's diagonal) following " + model.table(SpringKind::shear).name() +
             compression_said(model.table(SpringKind::shear));
    case Role::bend: {
      char text[200];
      std::snprintf(text, sizeof text,
                    "bending: skip-one bend springs, linear in tension and compression, %.6g N/m per width",
                    model.table(SpringKind::bend).tension(1.0));
      return text;
    }
  }
  return "";
}

Eigen::Vector3d SpringTerm::force_at(const Model& model, const Positions& x, int node,
                                     const Eigen::Vector3d& at) const {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const int s : model.fabric.springs_at(node)) {
    const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
    if (!covers(spring.kind)) continue;
    force += spring.a == node ? spring_path_force(model, spring, at, at_index(x, spring.b), node)
                              : spring_path_force(model, spring, at_index(x, spring.a), at, node);
  }
  return force;
}

double SpringTerm::energy(const Model& model, const Positions& x) const {
  const std::vector<Spring>& springs = model.fabric.springs();
  return sum_in_index_order(static_cast<std::ptrdiff_t>(springs.size()), [&](std::ptrdiff_t i) {
    const Spring& spring = springs[static_cast<std::size_t>(i)];
    return covers(spring.kind) ? spring_path_energy(model, spring, at_index(x, spring.a), at_index(x, spring.b)) : 0.0;
  });
}

double SpringTerm::node_energy(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const {
  double energy = 0.0;
  for (const int s : model.fabric.springs_at(node)) {
    const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
    if (!covers(spring.kind)) continue;
    energy += spring.a == node ? spring_path_energy(model, spring, at, at_index(x, spring.b))
                               : spring_path_energy(model, spring, at_index(x, spring.a), at);
  }
  return energy;
}

double SpringTerm::node_energy_change(const Model& model, const Positions& x, int node,
                                      const Eigen::Vector3d& at) const {
  return node_energy(model, x, node, at) - node_energy(model, x, node, at_index(x, node));
}

void SpringTerm::add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const {
  const std::vector<Spring>& springs = model.fabric.springs();
  std::vector<Eigen::Matrix3d> stiffness(springs.size());
  // A spring over an edge couples its ends by a full 6 × 6 block; kept only where a body wraps.
  const bool wraps = model.wraps_edges();
  std::vector<std::optional<Matrix6d>> wrapped(wraps ? springs.size() : 0);
  // Per kind this term covers, the slack floor's slope (N/m per unit strain), found once.
  std::array<double, 4> slack_slope{};
  for (const SpringKind kind : {SpringKind::warp, SpringKind::weft, SpringKind::shear, SpringKind::bend})
    if (covers(kind) && sink.slack_share() > 0.0)
      slack_slope[static_cast<std::size_t>(kind)] = sink.slack_share() * model.table(kind).steepest_slope();
#pragma omp parallel for schedule(static) if (springs.size() >= kMinParallelItems)
  for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(springs.size()); ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Spring& s = springs[k];
    if (!covers(s.kind)) continue;
    const Eigen::Vector3d &xa = at_index(x, s.a), &xb = at_index(x, s.b);
    if (wraps)
      if (const auto wrap = spring_wrap(model, s, xa, xb)) {
        wrapped[k] = wrapped_spring_hessian(xa, xb, *wrap, s, model.table(s.kind), true);
        continue;
      }
    const double slack_axial = s.width * slack_slope[static_cast<std::size_t>(s.kind)] / s.rest_length;
    stiffness[k] = projected_spring_stiffness(xa, xb, s, model.table(s.kind), slack_axial);
  }
  sink.add_each(springs.size(), [&](std::size_t i, StiffnessSink& part) {
    if (!covers(springs[i].kind)) return;
    const int a = springs[i].a, b = springs[i].b;
    if (wraps && wrapped[i]) {
      const Matrix6d& h = *wrapped[i];
      part.add(a, a, h.topLeftCorner<3, 3>());
      part.add(b, b, h.bottomRightCorner<3, 3>());
      part.add(a, b, h.topRightCorner<3, 3>());
      return;
    }
    // A straight spring between a and b adds [[K, −K], [−K, K]].
    part.add(a, a, stiffness[i]);
    part.add(b, b, stiffness[i]);
    part.add(b, a, -stiffness[i]);
  });
}

void SpringTerm::bound_stiffness(const Model& model, StiffnessBound& bound) const {
  for (const Spring& s : model.fabric.springs()) {
    if (!covers(s.kind)) continue;
    const double k = s.width * model.table(s.kind).steepest_slope() / s.rest_length;
    bound.per_node[static_cast<std::size_t>(s.a)] += k;
    bound.per_node[static_cast<std::size_t>(s.b)] += k;
    bound.stiffest_element = std::max(bound.stiffest_element, k);
  }
}

}  // namespace fabform
