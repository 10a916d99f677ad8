#include "fabform/analysis/draw_in.hpp"

#include <cmath>
#include <limits>

namespace fabform {
namespace {

// The outward normal of the flat fabric's edge at an edge node, in x and y.
Eigen::Vector2d outward(const Fabric& fabric, int node) {
  const FabricSpec& spec = fabric.spec();
  if (spec.shape == FabricSpec::Shape::circle)
    return (fabric.rest_position(node).head<2>() - Eigen::Vector2d(spec.radius_m(), spec.radius_m())).normalized();
  const int i = fabric.i_of(node), j = fabric.j_of(node);
  const Eigen::Vector2d n((i == fabric.nodes_warp() - 1) - (i == 0), (j == fabric.nodes_weft() - 1) - (j == 0));
  return n.normalized();
}

}  // namespace

DrawIn draw_in(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  DrawIn d;
  d.per_node_m.assign(x.size(), std::numeric_limits<double>::quiet_NaN());
  // A garment's panels are not a blank drawn in: they start apart, placed round a body.
  if (model.fabric.spec().shape == FabricSpec::Shape::panels) return d;
  for (int k = 0; k < model.node_count(); ++k) {
    if (!model.fabric.on_perimeter(k)) continue;
    const auto i = static_cast<std::size_t>(k);
    const double inwards = -(x[i] - model.start[i]).head<2>().dot(outward(model.fabric, k));
    d.per_node_m[i] = inwards;
    if (d.max_node < 0 || inwards > d.max_m) d.max_m = inwards, d.max_node = k;
  }
  return d;
}

}  // namespace fabform
