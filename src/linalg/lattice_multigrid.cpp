#include "linalg/lattice_multigrid.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "linalg/galerkin_product.hpp"
#include "linalg/sparse_transpose.hpp"

namespace fabform {

namespace {

// The coarsest lattice has at most this many points a side: factorised whole, it costs less
// than a smoothing sweep on the finest level.
constexpr int kCoarsestSide = 24;
// Sweeps before and after each coarse correction: on the dome at 201 × 201 nodes (newton to
// 1e-6 N, one thread), 1 took 43 Newton iterations and 9.95 s, 2 took 40 and 11.17 s (trial
// builds, one run each).
constexpr int kSweeps = 1;

// The coarsest matrix made factorisable: 1 on the diagonal of points no finer unknown reaches
// (their rows and columns are empty), and a shift of 1e-10 of the mean diagonal, for a coarse
// move that no finer unknown can make (a point amid nodes pressed on one plane, moving along
// its normal), which the Galerkin product leaves without stiffness.
Eigen::SparseMatrix<double> factorisable(const RowMatrix& a) {
  Eigen::SparseMatrix<double> m = a;
  const double shift = 1e-10 * m.diagonal().mean();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (m.coeff(i, i) <= 0.0) m.coeffRef(i, i) = 1.0;
    m.coeffRef(i, i) += shift;
  }
  return m;
}

// Each unknown's lattice point: on the finest level its node's.
std::vector<std::array<int, 2>> unknown_places(const LatticeUnknowns& unknowns) {
  std::vector<std::array<int, 2>> place;
  place.reserve(unknowns.node.size());
  for (const int node : unknowns.node) place.push_back(unknowns.node_lattice[static_cast<std::size_t>(node)]);
  return place;
}

// Each unknown's lattice point on a coarser level: 3 unknowns a point, point i + size[0]·j.
std::vector<std::array<int, 2>> level_places(std::array<int, 2> size, Eigen::Index unknowns) {
  std::vector<std::array<int, 2>> place(static_cast<std::size_t>(unknowns));
  for (Eigen::Index u = 0; u < unknowns; ++u) {
    const int point = static_cast<int>(u / 3);
    place[static_cast<std::size_t>(u)] = {point % size[0], point / size[0]};
  }
  return place;
}

}  // namespace

void LatticeMultigrid::set_matrix(const Eigen::SparseMatrix<double>& lower, const LatticeUnknowns& unknowns) {
  if (lower.rows() == 0 || static_cast<Eigen::Index>(unknowns.node.size()) != lower.rows())
    throw std::invalid_argument("LatticeMultigrid: an empty matrix or an unknown's node missing");
  levels_.clear();
  // Eigen 3.4's sparse matrices have no move constructor or assignment: std::move copies them.
  // The matrices are handed on by swap, and the levels built in place (a deque never moves its
  // elements), so no level's matrices are ever held twice. They are kept only once the
  // hierarchy is whole, so a failure leaves none.
  std::deque<Level> levels;
  RowMatrix a = whole_symmetric(lower);
  RowMatrix p = unknown_prolongation(unknowns);
  std::array<int, 2> size = coarser_lattice(unknowns.lattice_size);
  std::vector<std::array<int, 2>> place = unknown_places(unknowns);
  for (;;) {
    Level& level = levels.emplace_back();
    level.a.swap(a);
    level.prolongation.swap(p);
    RowMatrix restriction = transposed(level.prolongation);
    level.restriction.swap(restriction);
    RowMatrix coarse = galerkin_product(level.restriction, level.a, level.prolongation);
    level.smoother = LineGaussSeidel(level.a, place);
    place = level_places(size, coarse.rows());
    a.swap(coarse);
    if (std::max(size[0], size[1]) <= kCoarsestSide) break;
    RowMatrix next = lattice_prolongation(size);
    p.swap(next);
    size = coarser_lattice(size);
  }
  coarsest_.compute(factorisable(a));
  if (coarsest_.info() != Eigen::Success)
    throw std::runtime_error("LatticeMultigrid: the coarsest level is not positive definite");
  levels_.swap(levels);
}

Eigen::VectorXd LatticeMultigrid::cycle(std::size_t index, const Eigen::VectorXd& b) const {
  if (index == levels_.size()) return coarsest_.solve(b);
  const Level& level = levels_[index];
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  for (int sweep = 0; sweep < kSweeps; ++sweep) level.smoother.sweep(level.a, b, x, true);
  const Eigen::VectorXd residual = b - level.a * x;
  x += level.prolongation * cycle(index + 1, level.restriction * residual);
  for (int sweep = 0; sweep < kSweeps; ++sweep) level.smoother.sweep(level.a, b, x, false);
  return x;
}

Eigen::VectorXd LatticeMultigrid::v_cycle(const Eigen::VectorXd& b) const {
  if (levels_.empty()) throw std::logic_error("LatticeMultigrid used before set_matrix");
  return cycle(0, b);
}

CgResult LatticeMultigrid::solve(const Eigen::VectorXd& b, double relative_tolerance, int max_iterations) const {
  if (levels_.empty()) throw std::logic_error("LatticeMultigrid::solve before set_matrix");
  if (b.size() != levels_.front().a.rows()) throw std::invalid_argument("LatticeMultigrid::solve: b has the wrong size");
  return preconditioned_cg(levels_.front().a, b, [this](const Eigen::VectorXd& r) { return v_cycle(r); },
                           relative_tolerance, max_iterations);
}

}  // namespace fabform
