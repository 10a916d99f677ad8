#include "linalg/line_gauss_seidel.hpp"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "fabform/thread_count.hpp"
#include "linalg/parallel_failure.hpp"
#include "linalg/sparse_diagonal.hpp"

namespace fabform {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Added to each line's diagonal, relative to the mean diagonal of `a`: a coarse level's matrix
// can be singular along a move no finer unknown makes (lattice_multigrid.cpp), and the shift
// keeps that move finite; it only damps the sweep, which stays convergent.
constexpr double kShift = 1e-10;

double mean_diagonal(const RowMatrix& a) {
  const double sum = sum_in_order(stored_diagonal(a, diagonal_positions(a)));
  return a.rows() > 0 && sum > 0.0 ? sum / static_cast<double>(a.rows()) : 1.0;
}

}  // namespace

LineGaussSeidel::LineGaussSeidel(const RowMatrix& a, const std::vector<std::array<int, 2>>& place) {
  if (static_cast<Eigen::Index>(place.size()) != a.rows() || a.rows() != a.cols())
    throw std::invalid_argument("LineGaussSeidel: a lattice point per unknown of a square matrix is needed");
  for (const std::array<int, 2>& p : place)
    if (p[0] < 0 || p[1] < 0) throw std::invalid_argument("LineGaussSeidel: a negative lattice index");
  rows_ = a.rows();
  nonzeros_ = a.nonZeros();
  const double shift = kShift * mean_diagonal(a);
  families_[0] = family(a, place, 0, shift);
  families_[1] = family(a, place, 1, shift);
}

LineGaussSeidel::Family LineGaussSeidel::family(const RowMatrix& a, const std::vector<std::array<int, 2>>& place,
                                                int along, double shift) {
  const auto across = static_cast<std::size_t>(1 - along);
  int count = 0;
  for (const std::array<int, 2>& p : place) count = std::max(count, p[across] + 1);
  Family out;
  std::vector<Line>& lines = out.lines;
  lines.resize(static_cast<std::size_t>(count));
  for (std::size_t u = 0; u < place.size(); ++u)
    lines[static_cast<std::size_t>(place[u][across])].unknowns.push_back(static_cast<int>(u));
  std::vector<int> line_of(place.size()), position(place.size()), reach(lines.size(), 0);
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (const int u : lines[l].unknowns) line_of[static_cast<std::size_t>(u)] = static_cast<int>(l);
  // Lines are factorised on every thread: each writes only its own unknowns' positions.
  ParallelFailure failure;
#pragma omp parallel for schedule(dynamic, 8) if (place.size() >= static_cast<std::size_t>(kMinParallelItems))
  for (std::size_t l = 0; l < lines.size(); ++l) {
    try {
      reach[l] = factorise(a, place, along, line_of, position, static_cast<int>(l), shift, lines[l]);
    } catch (...) {
      failure.capture();
    }
  }
  failure.rethrow();
  split(out, std::accumulate(reach.begin(), reach.end(), 0, [](int m, int r) { return std::max(m, r); }));
  return out;
}

// The seam: after the first half of the unknowns, the lines `reach` (the farthest any line's
// couplings go across the lines) after it, so that no line before the seam couples to one after
// it. A small level, or one of too few lines, keeps one run.
void LineGaussSeidel::split(Family& family, int reach) {
  const std::vector<Line>& lines = family.lines;
  family.seam = family.seam_end = lines.size();
  std::size_t unknowns = 0;
  for (const Line& line : lines) unknowns += line.unknowns.size();
  if (unknowns < static_cast<std::size_t>(kMinParallelItems)) return;
  std::size_t seam = 0, first_half = 0;
  while (seam < lines.size() && 2 * first_half < unknowns) first_half += lines[seam++].unknowns.size();
  const std::size_t seam_end = seam + static_cast<std::size_t>(reach);
  if (seam_end >= lines.size()) return;
  family.seam = seam;
  family.seam_end = seam_end;
}

// Sorts line `id`'s unknowns along it and factorises its block of a, shifted. Returns how many
// lines across its unknowns' couplings reach.
int LineGaussSeidel::factorise(const RowMatrix& a, const std::vector<std::array<int, 2>>& place, int along,
                                const std::vector<int>& line_of, std::vector<int>& position, int id, double shift,
                                Line& line) {
  std::stable_sort(line.unknowns.begin(), line.unknowns.end(), [&](int s, int t) {
    return place[static_cast<std::size_t>(s)][static_cast<std::size_t>(along)] <
           place[static_cast<std::size_t>(t)][static_cast<std::size_t>(along)];
  });
  const auto m = static_cast<int>(line.unknowns.size());
  if (m == 0) return 0;
  for (int k = 0; k < m; ++k) position[static_cast<std::size_t>(line.unknowns[static_cast<std::size_t>(k)])] = k;
  // The block's lower triangle, row by row (row k's entries left of the diagonal), and its
  // bandwidth, the farthest of them from the diagonal.
  std::vector<double> diagonal(static_cast<std::size_t>(m), 0.0);
  std::vector<std::tuple<int, int, double>> below;
  int bandwidth = 0, reach = 0;
  for (int k = 0; k < m; ++k) {
    const int u = line.unknowns[static_cast<std::size_t>(k)];
    for (RowMatrix::InnerIterator it(a, u); it; ++it) {
      const auto c = static_cast<std::size_t>(it.col());
      reach = std::max(reach, std::abs(line_of[c] - id));
      if (line_of[c] != id) continue;
      if (it.col() == u) {
        diagonal[static_cast<std::size_t>(k)] = it.value();
      } else if (position[c] < k) {
        below.emplace_back(k, position[c], it.value());
        bandwidth = std::max(bandwidth, k - position[c]);
      }
    }
  }
  line.factor = BandedLdlt(m, bandwidth);
  // A point no finer unknown reaches has an empty row, and in the V-cycle no residual (the
  // restriction's row there is empty too): 1 keeps it where it is.
  for (int k = 0; k < m; ++k) {
    const double d = diagonal[static_cast<std::size_t>(k)];
    line.factor.at(k, k) = (d > 0.0 ? d : 1.0) + shift;
  }
  for (const auto& [row, column, value] : below) line.factor.at(row, column) = value;
  if (!line.factor.factorise()) throw std::runtime_error("LineGaussSeidel: a line's block could not be factorised");
  return reach;
}

// The line's unknowns corrected by its block's solve of their residual:
// x_L += Ã_LL⁻¹ (b_L − (A x)_L), Ã_LL the shifted block. With the block exact this is the line's
// solve given the others; in this form the shift keeps each correction A-self-adjoint, so the
// backward sweep stays the forward one's adjoint.
void LineGaussSeidel::relax(const RowMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x, const Line& line) {
  const auto m = static_cast<Eigen::Index>(line.unknowns.size());
  if (m == 0) return;
  const int* row_start = a.outerIndexPtr();
  const int* column = a.innerIndexPtr();
  const double* value = a.valuePtr();
  Eigen::VectorXd r(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const int u = line.unknowns[static_cast<std::size_t>(k)];
    double sum = b[u];
    for (int p = row_start[u]; p < row_start[u + 1]; ++p) sum -= value[p] * x[column[p]];
    r[k] = sum;
  }
  line.factor.solve_in_place(r);
  for (Eigen::Index k = 0; k < m; ++k) x[line.unknowns[static_cast<std::size_t>(k)]] += r[k];
}

void LineGaussSeidel::relax_lines(const RowMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                  const Family& family, std::size_t begin, std::size_t end, bool forward) {
  if (forward)
    for (std::size_t l = begin; l < end; ++l) relax(a, b, x, family.lines[l]);
  else
    for (std::size_t l = end; l-- > begin;) relax(a, b, x, family.lines[l]);
}

// Forward: both halves, then the seam; backward, the reverse. The halves neither read nor write
// each other's unknowns (the seam's they only read), so they run at once.
void LineGaussSeidel::pass(const RowMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x, const Family& family,
                           bool forward) {
  const std::size_t end = family.lines.size();
  if (family.seam_end == end) {  // one run
    relax_lines(a, b, x, family, 0, end, forward);
    return;
  }
  if (!forward) relax_lines(a, b, x, family, family.seam, family.seam_end, false);
  on_each_side([&](int half) {
    if (half == 0)
      relax_lines(a, b, x, family, 0, family.seam, forward);
    else
      relax_lines(a, b, x, family, family.seam_end, end, forward);
  });
  if (forward) relax_lines(a, b, x, family, family.seam, family.seam_end, true);
}

void LineGaussSeidel::sweep(const RowMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x, bool forward) const {
  // The halves' independence rests on the couplings of the matrix the lines were made from.
  if (a.rows() != rows_ || a.nonZeros() != nonzeros_)
    throw std::invalid_argument("LineGaussSeidel::sweep: not the matrix the lines were made from");
  if (forward) {
    pass(a, b, x, families_[0], true);
    pass(a, b, x, families_[1], true);
  } else {
    pass(a, b, x, families_[1], false);
    pass(a, b, x, families_[0], false);
  }
}

}  // namespace fabform
