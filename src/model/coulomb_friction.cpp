#include "fabform/model/coulomb_friction.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "fabform/fabric/fabric.hpp"

namespace fabform {
namespace {

Eigen::Matrix3d plane_across(const Eigen::Vector3d& normal) {
  return Eigen::Matrix3d::Identity() - normal * normal.transpose();
}

}  // namespace

CoulombFriction::CoulombFriction(std::vector<FrictionContact> contacts, double creep_m, int node_count)
    : contacts_(std::move(contacts)), creep_m_(creep_m), slot_(static_cast<std::size_t>(node_count), -1) {
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    slot_[static_cast<std::size_t>(contacts_[i].node)] = static_cast<int>(i);
}

std::string CoulombFriction::describe(const Model& /*model*/) const {
  char text[160];
  std::snprintf(text, sizeof text, "friction: smoothed Coulomb potential on %zu nodes, creep %.3g m",
                contacts_.size(), creep_m_);
  return text;
}

const FrictionContact* CoulombFriction::contact_of(int node) const {
  const int slot = slot_[static_cast<std::size_t>(node)];
  return slot < 0 ? nullptr : &contacts_[static_cast<std::size_t>(slot)];
}

bool CoulombFriction::stuck(int node, const Eigen::Vector3d& at) const {
  const FrictionContact* c = contact_of(node);
  return c && slip(*c, at).norm() < creep_m_;
}

Eigen::Vector3d CoulombFriction::slip(const FrictionContact& c, const Eigen::Vector3d& at) const {
  return plane_across(c.normal) * (at - c.anchor);
}

double CoulombFriction::node_energy(const FrictionContact& c, const Eigen::Vector3d& at) const {
  const double y = slip(c, at).norm();
  const double e = creep_m_;
  const double f0 = y < e ? y * y / e - y * y * y / (3.0 * e * e) + e / 3.0 : y;
  return c.limit_N * f0;
}

Eigen::Vector3d CoulombFriction::force_at(const Model& /*model*/, const Positions& /*x*/, int node,
                                         const Eigen::Vector3d& at) const {
  const FrictionContact* c = contact_of(node);
  if (!c) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d u = slip(*c, at);
  const double y = u.norm();
  if (y == 0.0) return Eigen::Vector3d::Zero();
  const double e = creep_m_;
  const double f1_over_y = y < e ? 2.0 / e - y / (e * e) : 1.0 / y;  // f1(y)/y
  return -c->limit_N * f1_over_y * u;
}

double CoulombFriction::energy(const Model& /*model*/, const Positions& x) const {
  double total = 0.0;
  for (const FrictionContact& c : contacts_) total += node_energy(c, x[static_cast<std::size_t>(c.node)]);
  return total;
}

double CoulombFriction::node_energy_change(const Model& /*model*/, const Positions& x, int node,
                                          const Eigen::Vector3d& at) const {
  const FrictionContact* c = contact_of(node);
  return c ? node_energy(*c, at) - node_energy(*c, x[static_cast<std::size_t>(node)]) : 0.0;
}

// ∇²D_k = μλ·P·[(f1/y)·I + (f1' − f1/y)/y² · u·uᵀ]·P: along the slip f1' ≥ 0, across it
// f1/y > 0, so it is positive semi-definite as it stands.
void CoulombFriction::add_stiffness(const Model& /*model*/, const Positions& x, StiffnessSink& sink) const {
  const double e = creep_m_;
  for (const FrictionContact& c : contacts_) {
    const Eigen::Matrix3d p = plane_across(c.normal);
    const Eigen::Vector3d u = slip(c, x[static_cast<std::size_t>(c.node)]);
    const double y = u.norm();
    Eigen::Matrix3d k;
    if (y < e) k = (2.0 / e - y / (e * e)) * Eigen::Matrix3d::Identity() - (y > 0.0 ? 1.0 / (e * e * y) : 0.0) * u * u.transpose();
    else k = (Eigen::Matrix3d::Identity() - u * u.transpose() / (y * y)) / y;
    sink.add(c.node, c.node, c.limit_N * p * k * p);
  }
}

double friction_creep_m(const Fabric& fabric, double fraction) {
  double total = 0.0;
  for (const Spring& s : fabric.springs()) total += s.rest_length;
  return fraction * total / static_cast<double>(std::max<std::size_t>(fabric.springs().size(), 1));
}

}  // namespace fabform
