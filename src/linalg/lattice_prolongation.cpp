#include "linalg/lattice_prolongation.hpp"

#include <algorithm>
#include <stdexcept>

namespace fabform {

namespace {

// A fine index's place between the coarse indices either side of it.
struct Between {
  int low = 0, high = 0;     // coarse indices
  double high_weight = 0.0;  // the low one's is 1 − high_weight
};

// Coarse index c sits on fine index min(2c, n − 1).
int fine_of(int coarse, int n) { return std::min(2 * coarse, n - 1); }

Between between(int i, int n) {
  const int low = i / 2;
  if (fine_of(low, n) == i) return {low, low, 0.0};
  const int high = low + 1;
  const int a = fine_of(low, n), b = fine_of(high, n);
  return {low, high, static_cast<double>(i - a) / (b - a)};
}

// The coarse lattice points, with weights, that a fine point (i, j) is interpolated from.
template <typename Add>
void for_each_weight(std::array<int, 2> fine, int i, int j, Add add) {
  const std::array<int, 2> coarse = coarser_lattice(fine);
  const Between u = between(i, fine[0]), v = between(j, fine[1]);
  const std::array<int, 2> us = {u.low, u.high}, vs = {v.low, v.high};
  const std::array<double, 2> uw = {1.0 - u.high_weight, u.high_weight}, vw = {1.0 - v.high_weight, v.high_weight};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      if (const double w = uw[a] * vw[b]; w != 0.0) add(us[a] + coarse[0] * vs[b], w);
}

void check_lattice(std::array<int, 2> size) {
  if (size[0] < 2 || size[1] < 2) throw std::invalid_argument("lattice prolongation: a lattice under 2 × 2 nodes");
}

}  // namespace

std::array<int, 2> coarser_lattice(std::array<int, 2> size) {
  check_lattice(size);
  return {size[0] / 2 + 1, size[1] / 2 + 1};
}

RowMatrix lattice_prolongation(std::array<int, 2> size) {
  const std::array<int, 2> coarse = coarser_lattice(size);
  const int points = size[0] * size[1];
  RowMatrix p(3 * points, 3 * coarse[0] * coarse[1]);
  p.reserve(Eigen::VectorXi::Constant(3 * points, 4));
  for (int j = 0; j < size[1]; ++j)
    for (int i = 0; i < size[0]; ++i)
      for_each_weight(size, i, j, [&](int c, double w) {
        for (int d = 0; d < 3; ++d) p.insert(3 * (i + size[0] * j) + d, 3 * c + d) = w;
      });
  p.makeCompressed();
  return p;
}

RowMatrix unknown_prolongation(const LatticeUnknowns& unknowns) {
  const std::array<int, 2> coarse = coarser_lattice(unknowns.lattice_size);
  const auto n = static_cast<Eigen::Index>(unknowns.node.size());
  if (unknowns.direction.size() != unknowns.node.size())
    throw std::invalid_argument("lattice prolongation: a direction per unknown missing");
  RowMatrix p(n, 3 * coarse[0] * coarse[1]);
  p.reserve(Eigen::VectorXi::Constant(n, 12));
  for (Eigen::Index u = 0; u < n; ++u) {
    const Eigen::Vector3d& d = unknowns.direction[static_cast<std::size_t>(u)];
    if (d.isZero(0.0)) continue;
    const std::array<int, 2> ij = unknowns.node_lattice[static_cast<std::size_t>(unknowns.node[u])];
    for_each_weight(unknowns.lattice_size, ij[0], ij[1], [&](int c, double w) {
      for (int a = 0; a < 3; ++a)
        if (d[a] != 0.0) p.insert(u, 3 * c + a) = w * d[a];
    });
  }
  p.makeCompressed();
  return p;
}

}  // namespace fabform
