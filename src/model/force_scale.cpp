#include "fabform/model/force_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fabform {

double spring_force_scale_N(const Model& model) {
  double scale = std::numeric_limits<double>::infinity();
  // The segment just above zero strain: a tension-only table's slope at 0 itself is the slack side's.
  const double just_stretched = std::numeric_limits<double>::min();
  for (const Spring& s : model.fabric.springs())
    if (s.kind == SpringKind::warp || s.kind == SpringKind::weft)
      scale = std::min(scale, s.width * model.table(s.kind).slope(just_stretched));
  return std::isfinite(scale) ? scale : 0.0;
}

}  // namespace fabform
