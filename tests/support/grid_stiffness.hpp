#pragma once
// Test matrices for the sparse Cholesky: the stiffness of a square grid of nodes with 3
// unknowns each, springs to the right and up with random 3 × 3 positive semi-definite blocks,
// plus a diagonal shift that makes it positive definite. Built as an Eigen matrix (the lower
// triangle, as Newton hands it over) and in CHOLMOD's layout.
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "linalg/cholmod_factor.hpp"
#include "linalg/lattice_prolongation.hpp"

namespace fabform::test {

inline Eigen::SparseMatrix<double> grid_stiffness(int side, double shift, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> lower;
  const auto add = [&](int a, int b, const Eigen::Matrix3d& k) {  // a spring a–b, a < b
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        if (r >= c) lower.emplace_back(3 * a + r, 3 * a + c, k(r, c));
        if (r >= c) lower.emplace_back(3 * b + r, 3 * b + c, k(r, c));
        lower.emplace_back(3 * b + r, 3 * a + c, -k(r, c));
      }
  };
  const auto block = [&] {
    Eigen::Matrix3d g;
    for (int i = 0; i < 9; ++i) g(i) = unit(rng);
    return Eigen::Matrix3d(g * g.transpose());
  };
  const int n = side * side;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const int k = j * side + i;
      if (i + 1 < side) add(k, k + 1, block());
      if (j + 1 < side) add(k, k + side, block());
    }
  for (int u = 0; u < 3 * n; ++u) lower.emplace_back(u, u, shift);
  Eigen::SparseMatrix<double> m(3 * n, 3 * n);
  m.setFromTriplets(lower.begin(), lower.end());
  m.makeCompressed();
  return m;
}

inline LowerCsc to_lower_csc(const Eigen::SparseMatrix<double>& m) {
  LowerCsc out;
  out.n = static_cast<int>(m.rows());
  out.start.assign(m.outerIndexPtr(), m.outerIndexPtr() + m.outerSize() + 1);
  out.row.assign(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros());
  out.value.assign(m.valuePtr(), m.valuePtr() + m.nonZeros());
  return out;
}

/// Unknowns 3 to a node, along x, y and z: each one's place in its node's displacement.
inline std::vector<int> xyz_components(Eigen::Index unknowns) {
  std::vector<int> c(static_cast<std::size_t>(unknowns));
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = static_cast<int>(i % 3);
  return c;
}

/// The grid as a lattice: node j·side + i at (i, j), its unknowns along x, y and z.
inline LatticeUnknowns grid_lattice(int side) {
  LatticeUnknowns l;
  l.lattice_size = {side, side};
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      l.node_lattice.push_back({i, j});
      for (int d = 0; d < 3; ++d) {
        l.node.push_back(j * side + i);
        l.direction.push_back(Eigen::Vector3d::Unit(d));
      }
    }
  return l;
}

/// The full symmetric matrix of a lower triangle, to multiply with.
inline Eigen::SparseMatrix<double> symmetric(const Eigen::SparseMatrix<double>& lower) {
  return lower.selfadjointView<Eigen::Lower>();
}

}  // namespace fabform::test
