#include "fabform/analysis/ply_figures.hpp"

#include <algorithm>

#include "fabform/analysis/self_intersections.hpp"
#include "fabform/model/self_contact.hpp"

namespace fabform {

std::optional<PlyFigures> ply_figures(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const std::vector<const SelfContact*> contact = terms_of<SelfContact>(model);
  if (contact.empty()) return std::nullopt;
  PlyFigures f;
  f.thickness_m = contact.front()->thickness_m();
  const std::vector<ProximityPair> pairs = contact.front()->pairs(x);
  f.contact_pairs = static_cast<int>(pairs.size());
  for (const ProximityPair& p : pairs) f.smallest_gap_m = std::min(f.smallest_gap_m.value_or(p.distance_m), p.distance_m);
  f.intersecting_triangle_pairs = count_self_intersections(model, x);
  return f;
}

}  // namespace fabform
