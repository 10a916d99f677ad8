#include "linalg/lattice_prolongation.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "fabform/thread_count.hpp"
#include "linalg/parallel_failure.hpp"

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

// A row-major matrix from its rows: `row(r, entry)` calls entry(column, value) for each of row r's
// entries, in any order and no column twice. Written straight into the compressed arrays (a pass
// to count, a pass to fill), each row sorted by column: Eigen's insert, which shifts each entry
// into its row's order, was 1.5 % of a multigrid Newton run on the dome at 401 × 401 nodes. Both
// passes run on every thread from 8192 rows (serial, they were 2 % of the main thread's samples
// at 1001 × 1001 nodes on two threads, the other one idle).
template <typename Row>
RowMatrix from_rows(Eigen::Index rows, Eigen::Index columns, Row row) {
  RowMatrix m(rows, columns);
  int* outer = m.outerIndexPtr();
  std::vector<Eigen::Index> size(static_cast<std::size_t>(rows) + 1, 0);  // per row, its entries; then where it starts
  const bool parallel = rows >= kMinParallelItems;
#pragma omp parallel for schedule(static) if (parallel)
  for (Eigen::Index r = 0; r < rows; ++r) row(r, [&](int, double) { ++size[static_cast<std::size_t>(r) + 1]; });
  for (std::size_t r = 1; r < size.size(); ++r) size[r] += size[r - 1];
  if (size.back() > std::numeric_limits<int>::max()) throw std::length_error("lattice prolongation: more than 2^31 entries");
  for (std::size_t r = 0; r < size.size(); ++r) outer[r] = static_cast<int>(size[r]);
  m.resizeNonZeros(size.back());
  ParallelFailure failure;
#pragma omp parallel if (parallel)
  {
    std::vector<std::pair<int, double>> entries;
#pragma omp for schedule(static)
    for (Eigen::Index r = 0; r < rows; ++r) {
      if (failure.caught()) continue;
      try {
        entries.clear();
        row(r, [&](int column, double value) { entries.emplace_back(column, value); });
      } catch (...) {
        failure.capture();
        continue;
      }
      std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t e = 0; e < entries.size(); ++e) {
        m.innerIndexPtr()[outer[r] + static_cast<Eigen::Index>(e)] = entries[e].first;
        m.valuePtr()[outer[r] + static_cast<Eigen::Index>(e)] = entries[e].second;
      }
    }
  }
  failure.rethrow();
  return m;
}

}  // namespace

std::array<int, 2> coarser_lattice(std::array<int, 2> size) {
  check_lattice(size);
  return {size[0] / 2 + 1, size[1] / 2 + 1};
}

RowMatrix lattice_prolongation(std::array<int, 2> size) {
  const std::array<int, 2> coarse = coarser_lattice(size);
  return from_rows(3 * size[0] * size[1], 3 * coarse[0] * coarse[1], [&](Eigen::Index row, const auto& entry) {
    const auto point = static_cast<int>(row / 3), d = static_cast<int>(row % 3);
    for_each_weight(size, point % size[0], point / size[0], [&](int c, double w) { entry(3 * c + d, w); });
  });
}

RowMatrix unknown_prolongation(const LatticeUnknowns& unknowns) {
  const std::array<int, 2> coarse = coarser_lattice(unknowns.lattice_size);
  if (unknowns.direction.size() != unknowns.node.size())
    throw std::invalid_argument("lattice prolongation: a direction per unknown missing");
  const auto n = static_cast<Eigen::Index>(unknowns.node.size());
  return from_rows(n, 3 * coarse[0] * coarse[1], [&](Eigen::Index u, const auto& entry) {
    const Eigen::Vector3d& d = unknowns.direction[static_cast<std::size_t>(u)];
    if (d.isZero(0.0)) return;
    const std::array<int, 2> ij = unknowns.node_lattice[static_cast<std::size_t>(unknowns.node[static_cast<std::size_t>(u)])];
    for_each_weight(unknowns.lattice_size, ij[0], ij[1], [&](int c, double w) {
      for (int a = 0; a < 3; ++a)
        if (d[a] != 0.0) entry(3 * c + a, w * d[a]);
    });
  });
}

}  // namespace fabform
