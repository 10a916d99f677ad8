#include "fabform/model/stretch_forces.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "fabform/fabric/spring.hpp"
#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/wind.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {
namespace {

// Units in the last place that a spring's length, from two coordinates and a rest length
// measured the same way, may be off by (a few for the difference, the norm and the rest).
constexpr double kLengthRoundings = 16.0;

}  // namespace

Eigen::Vector3d node_force_at(const Model& model, const std::vector<Eigen::Vector3d>& x, int node,
                              const Eigen::Vector3d& at) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const int s : model.fabric.springs_at(node)) {
    const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
    const int other = spring.a == node ? spring.b : spring.a;
    force += spring_force_on_a(at, x[static_cast<std::size_t>(other)], spring,
                               model.table(spring.kind));
  }
  if (model.bending_rigidity_Nm) force += bending_force_at(model, x, node, at);
  if (!model.loads.empty()) force += model.loads[static_cast<std::size_t>(node)];
  if (model.wind)  // at rest; dynamic adds the drag of the node's own velocity
    force += wind_force(*model.wind, model.fabric.node_areas()[static_cast<std::size_t>(node)],
                        node_normal(model.fabric, x, node, at), Eigen::Vector3d::Zero());
  return force;
}

double deformation_sum(const Model& model, const std::vector<Eigen::Vector3d>& x, int node) {
  double sum = 0.0;
  for (const int s : model.fabric.springs_at(node)) {
    const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
    const Eigen::Vector3d& a = x[static_cast<std::size_t>(spring.a)];
    const Eigen::Vector3d& b = x[static_cast<std::size_t>(spring.b)];
    const double deformation = std::abs((b - a).norm() - spring.rest_length);
    // A length computed from coordinates is only as exact as they are: a fabric laid out at
    // rest reads deformations of ~1e-17 m, and relax's step Σ|d|/C would then be as small.
    const double rounding =
        kLengthRoundings * std::numeric_limits<double>::epsilon() *
        std::max({a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff(), spring.rest_length});
    if (deformation > rounding) sum += deformation;
  }
  return sum;
}

double stretch_energy(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const std::vector<Spring>& springs = model.fabric.springs();
  const auto count = static_cast<std::ptrdiff_t>(springs.size());
  // Each spring's energy in parallel, summed in spring order: the same bits for any thread
  // count, so a line search decides alike on 1 or 2 threads (a reduction's order would not).
  std::vector<double> energies(springs.size());
#pragma omp parallel for schedule(static) if (count >= kMinParallelItems)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    const Spring& spring = springs[static_cast<std::size_t>(i)];
    energies[static_cast<std::size_t>(i)] =
        spring_energy(x[static_cast<std::size_t>(spring.a)], x[static_cast<std::size_t>(spring.b)],
                      spring, model.table(spring.kind));
  }
  double energy = 0.0;
  for (const double e : energies) energy += e;
  return energy;
}

NodeStrains node_strains(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const auto n = static_cast<std::size_t>(model.node_count());
  NodeStrains strains{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  std::vector<int> warp_count(n, 0), weft_count(n, 0);
  for (const Spring& spring : model.fabric.springs()) {
    if (spring.kind != SpringKind::warp && spring.kind != SpringKind::weft) continue;
    const auto a = static_cast<std::size_t>(spring.a), b = static_cast<std::size_t>(spring.b);
    const double strain = spring_strain(x[a], x[b], spring.rest_length);
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
