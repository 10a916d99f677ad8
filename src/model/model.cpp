#include "fabform/model/model.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <utility>

#include "fabform/model/spring_term.hpp"

namespace fabform {
namespace {

bool has_springs(const Fabric& fabric, SpringKind kind) {
  return std::any_of(fabric.springs().begin(), fabric.springs().end(),
                     [&](const Spring& s) { return s.kind == kind; });
}

}  // namespace

Model::Model(Fabric fabric_, TensionTable warp_, TensionTable weft_, std::vector<AxisMask> locks_,
             std::vector<RigidBody> bodies_, std::vector<Eigen::Vector3d> start_)
    : fabric(std::move(fabric_)),
      warp(std::move(warp_)),
      weft(std::move(weft_)),
      locks(std::move(locks_)),
      bodies(std::move(bodies_)),
      start(std::move(start_)) {
  terms.push_back(std::make_shared<SpringTerm>(SpringTerm::Role::stretch));
  if (has_springs(fabric, SpringKind::shear)) terms.push_back(std::make_shared<SpringTerm>(SpringTerm::Role::shear));
  if (has_springs(fabric, SpringKind::bend)) terms.push_back(std::make_shared<SpringTerm>(SpringTerm::Role::bend));
}

std::vector<std::string> Model::modelled() const {
  std::vector<std::string> lines;
  for (const auto& term : terms) lines.push_back(term->describe(*this));
  for (const RigidBody& body : bodies)
    if (body.friction() > 0.0) {
      char text[200];
      std::snprintf(text, sizeof text, "friction: Coulomb, mu = %.6g on body '%s' (stick and slip)", body.friction(),
                    body.name().c_str());
      lines.push_back(text);
    }
  for (const RigidBody& body : bodies)
    if (body.wrap_angle_deg() > 0.0) {
      char text[240];
      std::snprintf(text, sizeof text,
                    "edge contact: springs wrap the %d convex edges of body '%s' whose faces turn by %.6g degrees or more",
                    body.sharp_edge_count(), body.name().c_str(), body.wrap_angle_deg());
      lines.push_back(text);
    }
  return lines;
}

bool Model::loaded() const {
  return std::any_of(terms.begin(), terms.end(), [](const auto& t) { return t->external(); });
}

bool Model::resists_bending() const {
  return std::any_of(terms.begin(), terms.end(), [](const auto& t) { return t->resists_bending(); });
}

bool Model::has_friction() const {
  return std::any_of(bodies.begin(), bodies.end(), [](const RigidBody& b) { return b.friction() > 0.0; });
}

bool Model::wraps_edges() const {
  return std::any_of(bodies.begin(), bodies.end(), [](const RigidBody& b) { return b.wrap_angle_deg() > 0.0; });
}

std::vector<NeedingPart> Model::parts_needing() const {
  std::vector<NeedingPart> parts;
  for (const auto& term : terms)
    if (!term->needs().empty()) {
      const std::string said = term->describe(*this);
      parts.push_back({said.substr(0, said.find(':')), term->needs()});
    }
  if (has_friction()) parts.push_back({"friction against the bodies", kBodyFrictionNeeds});
  if (wraps_edges()) parts.push_back({"springs wrapped over edges", kWrappedEdgeNeeds});
  return parts;
}

SolverNeeds Model::solver_needs() const {
  SolverNeeds needs;
  for (const NeedingPart& part : parts_needing()) needs = needs | part.needs;
  return needs;
}

int Model::load_steps() const {
  int steps = 0;
  for (const ToolPath& path : paths) steps = std::max(steps, path.steps);
  return steps;
}

std::vector<Eigen::Vector3d> node_forces(const Model& model, const Positions& x) {
  std::vector<Eigen::Vector3d> forces(x.size(), Eigen::Vector3d::Zero());
  for (const auto& term : model.terms) term->add_forces(model, x, forces);
  return forces;
}

Eigen::Vector3d node_force_at(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const auto& term : model.terms) force += term->force_at(model, x, node, at);
  return force;
}

}  // namespace fabform
