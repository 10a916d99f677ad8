#include "fabform/model/clamp_frame.hpp"

#include <cmath>
#include <cstdio>
#include <utility>

namespace fabform {
namespace {

// Each node's limit 2·μ·N_k: the holder's force shared by area, friction on both faces.
std::vector<FrictionContact> holder_contacts(const Fabric& fabric, const std::vector<int>& nodes,
                                             const ClampOptions& options, const Positions& start) {
  double area = 0.0;
  for (const int k : nodes) area += fabric.node_areas()[static_cast<std::size_t>(k)];
  std::vector<FrictionContact> contacts;
  for (const int k : nodes) {
    const double share = fabric.node_areas()[static_cast<std::size_t>(k)] / area;
    contacts.push_back({k, 2.0 * options.friction * options.force_N * share, Eigen::Vector3d::UnitZ(),
                        start[static_cast<std::size_t>(k)]});
  }
  return contacts;
}

}  // namespace

std::string ClampOptions::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  // 1e6 N is a hundred tonnes on a blank: beyond, a unit mistake.
  if (!(force_N >= 0.0 && force_N <= 1e6)) return bad("force_N", "must be in [0, 1e6] N (the holder's whole force)");
  if (!(friction >= 0.0 && friction <= 10.0)) return bad("friction", "Coulomb's coefficient must be in [0, 10]");
  if (!(creep_m > 0.0 && std::isfinite(creep_m))) return bad("creep_m", "must be positive");
  return "";
}

ClampFrame::ClampFrame(const Fabric& fabric, std::vector<int> nodes, const ClampOptions& options,
                       const Positions& start)
    : nodes_(std::move(nodes)),
      options_(options),
      friction_(holder_contacts(fabric, nodes_, options, start), options.creep_m, fabric.node_count()) {}

std::string ClampFrame::describe(const Model& /*model*/) const {
  char text[240];
  std::snprintf(text, sizeof text,
                "clamp: blank holder pressing %zu nodes with %.6g N in all, held in z, drawing in past 2 * mu * N "
                "per node, mu = %.6g (creep %.3g m)",
                nodes_.size(), options_.force_N, options_.friction, options_.creep_m);
  return text;
}

}  // namespace fabform
