#include "fabform/fabric/grid.hpp"

#include <cmath>
#include <stdexcept>

namespace fabform {
namespace {

void validate(const GridSpec& spec) {
  if (!(std::isfinite(spec.width_m) && spec.width_m > 0.0) ||
      !(std::isfinite(spec.height_m) && spec.height_m > 0.0))
    throw std::invalid_argument("fabric size must be positive and finite");
  if (spec.divisions_warp < 1 || spec.divisions_weft < 1)
    throw std::invalid_argument("fabric divisions must be at least 1");
  if ((static_cast<long long>(spec.divisions_warp) + 1) *
          (static_cast<long long>(spec.divisions_weft) + 1) >
      50'000'000LL)
    throw std::invalid_argument("fabric has more than 50 million nodes");
}

// A spring on the fabric's edge stands for half a strip (seed 003, Figure 3).
double strip_width(int index, int last, double spacing) {
  return (index == 0 || index == last) ? 0.5 * spacing : spacing;
}

}  // namespace

FabricGrid::FabricGrid(const GridSpec& spec) : spec_(spec) {
  validate(spec);
  n_ = spec.divisions_warp + 1;
  m_ = spec.divisions_weft + 1;
  springs_at_.assign(static_cast<std::size_t>(node_count()), {-1, -1, -1, -1});
  springs_.reserve(static_cast<std::size_t>(2 * node_count()));
  for (int j = 0; j < m_; ++j)
    for (int i = 0; i + 1 < n_; ++i)
      add_spring(node(i, j), node(i + 1, j), spacing_warp(), strip_width(j, m_ - 1, spacing_weft()),
                 Direction::warp);
  for (int j = 0; j + 1 < m_; ++j)
    for (int i = 0; i < n_; ++i)
      add_spring(node(i, j), node(i, j + 1), spacing_weft(), strip_width(i, n_ - 1, spacing_warp()),
                 Direction::weft);
}

void FabricGrid::add_spring(int a, int b, double rest_length, double width, Direction direction) {
  const int index = static_cast<int>(springs_.size());
  springs_.push_back({a, b, rest_length, width, direction});
  // Slots: 0 warp towards -x, 1 warp towards +x, 2 weft towards -y, 3 weft towards +y.
  const int base = direction == Direction::warp ? 0 : 2;
  springs_at_[static_cast<std::size_t>(a)][static_cast<std::size_t>(base + 1)] = index;
  springs_at_[static_cast<std::size_t>(b)][static_cast<std::size_t>(base)] = index;
}

bool FabricGrid::on_perimeter(int node) const {
  const int i = i_of(node), j = j_of(node);
  return i == 0 || j == 0 || i == n_ - 1 || j == m_ - 1;
}

std::vector<double> FabricGrid::node_areas() const {
  std::vector<double> area(static_cast<std::size_t>(node_count()), 0.0);
  for (const Spring& s : springs_) {
    const double share = s.width * s.rest_length / 4.0;
    area[static_cast<std::size_t>(s.a)] += share;
    area[static_cast<std::size_t>(s.b)] += share;
  }
  return area;
}

Eigen::Vector3d FabricGrid::rest_position(int node) const {
  return {i_of(node) * spacing_warp(), j_of(node) * spacing_weft(), 0.0};
}

}  // namespace fabform
