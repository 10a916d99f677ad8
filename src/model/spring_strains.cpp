#include "fabform/model/spring_strains.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "fabform/model/spring_path.hpp"

namespace fabform {
namespace {

// Units in the last place that a spring's length, from two coordinates and a rest length
// measured the same way, may be off by (a few for the difference, the norm and the rest).
constexpr double kLengthRoundings = 16.0;

}  // namespace

double deformation_sum(const Model& model, const std::vector<Eigen::Vector3d>& x, int node) {
  double sum = 0.0;
  for (const int s : model.fabric.springs_at(node)) {
    const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
    const Eigen::Vector3d& a = x[static_cast<std::size_t>(spring.a)];
    const Eigen::Vector3d& b = x[static_cast<std::size_t>(spring.b)];
    const double deformation = std::abs(spring_path_length(model, spring, a, b) - spring.rest_length);
    // A length computed from coordinates is only as exact as they are: a fabric laid out at
    // rest reads deformations of ~1e-17 m, and relax's step Σ|d|/C would then be as small.
    const double rounding =
        kLengthRoundings * std::numeric_limits<double>::epsilon() *
        std::max({a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff(), spring.rest_length});
    if (deformation > rounding) sum += deformation;
  }
  return sum;
}

NodeStrains node_strains(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const auto n = static_cast<std::size_t>(model.node_count());
  NodeStrains strains{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  std::vector<int> warp_count(n, 0), weft_count(n, 0);
  for (const Spring& spring : model.fabric.springs()) {
    if (spring.kind != SpringKind::warp && spring.kind != SpringKind::weft) continue;
    const auto a = static_cast<std::size_t>(spring.a), b = static_cast<std::size_t>(spring.b);
    const double strain = spring_path_strain(model, spring, x[a], x[b]);
    auto& field = spring.kind == SpringKind::warp ? strains.warp : strains.weft;
    auto& count = spring.kind == SpringKind::warp ? warp_count : weft_count;
    field[a] += strain, field[b] += strain;
    ++count[a], ++count[b];
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (warp_count[k] > 0) strains.warp[k] /= warp_count[k];
    if (weft_count[k] > 0) strains.weft[k] /= weft_count[k];
  }
  return strains;
}

}  // namespace fabform
