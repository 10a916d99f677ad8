#include "fabform/analysis/garment_ease.hpp"

#include <algorithm>
#include <limits>

#include "fabform/geometry/nearby_queries.hpp"
#include "fabform/model/equilibrium.hpp"

namespace fabform {

std::optional<GarmentEase> garment_ease(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  if (model.fabric.panels().empty() || model.bodies.empty()) return std::nullopt;
  GarmentEase ease;
  ease.node_m.resize(x.size());
  NearbyQueries queries(model.bodies);
  for (std::size_t k = 0; k < x.size(); ++k) ease.node_m[k] = nearest_surface(model, queries, x[k]).point.signed_distance;
  const std::vector<double>& area = model.fabric.node_areas();
  for (const PanelMesh& panel : model.fabric.panels()) {
    PanelEase e{panel.name, 0.0, -std::numeric_limits<double>::infinity()};
    double weight = 0.0;
    for (int k = panel.first_node; k < panel.first_node + panel.node_count; ++k) {
      const auto n = static_cast<std::size_t>(k);
      e.mean_m += area[n] * ease.node_m[n];
      weight += area[n];
      e.max_m = std::max(e.max_m, ease.node_m[n]);
    }
    e.mean_m /= weight;
    ease.panels.push_back(e);
  }
  return ease;
}

}  // namespace fabform
