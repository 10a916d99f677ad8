#include "fabform/model/contact_penalty.hpp"

#include "fabform/model/force_scale.hpp"
#include "fabform/model/model.hpp"

namespace fabform {

double mean_surface_spring_length(const Fabric& fabric) {
  double sum = 0.0;
  int count = 0;
  for (const Spring& s : fabric.springs())
    if (s.kind == SpringKind::warp || s.kind == SpringKind::weft) sum += s.rest_length, ++count;
  return count > 0 ? sum / count : 0.0;
}

double contact_stiffness(const Model& model, double ratio) {
  const double length = mean_surface_spring_length(model.fabric);
  const double scale = spring_force_scale_N(model);
  return length > 0.0 && scale > 0.0 ? ratio * scale / length : 0.0;
}

OnsetPenalty onset_penalty(double depth_m, double stiffness_N_m, double onset_m) {
  const double d = depth_m, k = stiffness_N_m, h = onset_m;
  if (d < h) return {k * d * d * d / (6.0 * h), k * d * d / (2.0 * h), k * d / h};
  return {k * (0.5 * d * d - 0.5 * h * d + h * h / 6.0), k * (d - 0.5 * h), k};
}

}  // namespace fabform
