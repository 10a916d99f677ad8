#include "linalg/substructured_cholesky.hpp"

#include <algorithm>
#include <cstddef>
#include <tuple>

#include "linalg/parallel_failure.hpp"

namespace fabform {
namespace {

// Vectors here are indexed by unknowns and entries, which CHOLMOD counts in int.
constexpr std::size_t at(int i) { return static_cast<std::size_t>(i); }

// LAPACK and BLAS (Fortran: the trailing arguments are the character arguments' lengths).
extern "C" {
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* beta, double* c, const int* ldc,
            std::size_t, std::size_t);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info, std::size_t);
void dpotrs_(const char* uplo, const int* n, const int* nrhs, const double* a, const int* lda,
             double* b, const int* ldb, int* info, std::size_t);
}

// The entries of `pattern` between unknowns that `local` numbers (≥ 0), renumbered, each in
// the lower triangle, with where its value is in `pattern`.
void gather_pattern(const LowerCsc& pattern, const std::vector<int>& local, int n, LowerCsc* out,
                    std::vector<int>* source) {
  std::vector<std::tuple<int, int, int>> entries;  // (column, row, source)
  for (int c = 0; c < pattern.n; ++c) {
    if (local[at(c)] < 0) continue;
    for (int k = pattern.start[at(c)]; k < pattern.start[at(c) + 1]; ++k) {
      const int r = pattern.row[at(k)];
      if (local[at(r)] < 0) continue;
      const int a = local[at(r)], b = local[at(c)];
      entries.emplace_back(std::min(a, b), std::max(a, b), k);
    }
  }
  std::sort(entries.begin(), entries.end());
  out->n = n;
  out->start.assign(at(n) + 1, 0);
  out->row.clear();
  source->clear();
  for (const auto& [col, row, k] : entries) {
    ++out->start[at(col) + 1];
    out->row.push_back(row);
    source->push_back(k);
  }
  for (int c = 0; c < n; ++c) out->start[at(c) + 1] += out->start[at(c)];
  out->value.assign(out->row.size(), 0.0);
}

// Whether the pattern joins the two sides directly, which a separator forbids.
bool sides_touch(const LowerCsc& pattern, const std::vector<int>& part) {
  for (int c = 0; c < pattern.n; ++c)
    for (int k = pattern.start[at(c)]; k < pattern.start[at(c) + 1]; ++k) {
      const int pr = part[at(pattern.row[at(k)])];
      const int pc = part[at(c)];
      if (pr != 2 && pc != 2 && pr != pc) return true;
    }
  return false;
}

}  // namespace

std::unique_ptr<SubstructuredCholesky> SubstructuredCholesky::split(const LowerCsc& pattern,
                                                                    int min_unknowns) {
  if (pattern.n < min_unknowns) return nullptr;
  const std::vector<int> part = vertex_bisection(pattern);
  int counts[3] = {0, 0, 0};
  for (int p : part) ++counts[p];
  if (counts[0] == 0 || counts[1] == 0 || counts[2] == 0 || counts[2] > kMaxSeparator ||
      sides_touch(pattern, part))
    return nullptr;

  std::unique_ptr<SubstructuredCholesky> split(new SubstructuredCholesky);
  std::vector<int> separator_index(part.size(), -1);
  for (int u = 0; u < pattern.n; ++u)
    if (part[at(u)] == 2) {
      separator_index[at(u)] = static_cast<int>(split->separator_.size());
      split->separator_.push_back(u);
    }
  for (int c = 0; c < pattern.n; ++c)
    for (int k = pattern.start[at(c)]; k < pattern.start[at(c) + 1]; ++k) {
      const int r = pattern.row[at(k)];
      const int sr = separator_index[at(r)], sc = separator_index[at(c)];
      if (sr >= 0 && sc >= 0)
        split->separator_entries_.push_back({std::max(sr, sc), std::min(sr, sc), k});
    }
  for (int s = 0; s < 2; ++s) {
    Side& side = split->sides_[at(s)];
    for (int u = 0; u < pattern.n; ++u)
      if (part[at(u)] == s) side.interior.push_back(u);
    std::vector<int> local(part.size(), -1);
    const int interior = static_cast<int>(side.interior.size());
    for (int k = 0; k < interior; ++k) local[at(side.interior[at(k)])] = k;
    for (std::size_t j = 0; j < split->separator_.size(); ++j)
      local[at(split->separator_[j])] = interior + static_cast<int>(j);
    // In turn, not on a thread each: ordering both at once changed the bits of an N = 1000
    // dome from run to run (METIS's random choices are not private to a call).
    if (!split->build_side(pattern, local, &side)) return nullptr;
  }
  return split;
}

// Orders the side's interior by nested dissection, with S after it. CHOLMOD's automatic choice
// picks AMD for a half grid, whose factorisation then took 0.74–0.92 s a side against 0.59–0.64 s
// (N = 401 dome, first iterations, timed once). The postordering keeps S last when its
// complement couples it into one chain at the elimination tree's root; that is checked, as a
// side whose interior falls apart from S could let a piece follow S.
bool SubstructuredCholesky::build_side(const LowerCsc& pattern, const std::vector<int>& local,
                                       Side* side) const {
  const int interior = static_cast<int>(side->interior.size());
  const int n = interior + static_cast<int>(separator_.size());
  gather_pattern(pattern, local, n, &side->matrix, &side->source);

  std::vector<int> interior_only(local);
  for (int& l : interior_only)
    if (l >= interior) l = -1;
  LowerCsc interior_pattern;
  std::vector<int> unused;
  gather_pattern(pattern, interior_only, interior, &interior_pattern, &unused);
  CholmodFactor ordering;
  ordering.analyse(interior_pattern, CholmodFactor::Ordering::nested_dissection);
  std::vector<int> given = ordering.order();
  for (int u = interior; u < n; ++u) given.push_back(u);

  side->factor.analyse_in_order(side->matrix, given);
  const std::vector<int> order = side->factor.order();
  side->tail_to_separator.resize(separator_.size());
  for (std::size_t a = 0; a < separator_.size(); ++a) {
    const int row = order[at(interior) + a];
    if (row < interior) return false;
    side->tail_to_separator[a] = row - interior;
  }
  return true;
}

// LₛLₛ' (dense, by BLAS), in the separator's own order, lower triangle.
Eigen::MatrixXd SubstructuredCholesky::schur_on_separator(const Side& side) const {
  const int m = static_cast<int>(separator_.size());
  Eigen::MatrixXd product = Eigen::MatrixXd::Zero(m, m);
  const double one = 1.0, zero = 0.0;
  dsyrk_("L", "N", &m, &m, &one, side.schur_factor.data(), &m, &zero, product.data(), &m, 1, 1);
  Eigen::MatrixXd reordered = Eigen::MatrixXd::Zero(m, m);
  for (int b = 0; b < m; ++b)
    for (int a = b; a < m; ++a) {
      const int i = side.tail_to_separator[at(a)];
      const int j = side.tail_to_separator[at(b)];
      reordered(std::max(i, j), std::min(i, j)) = product(a, b);
    }
  return reordered;
}

bool SubstructuredCholesky::factorize(const LowerCsc& m) {
  std::array<Eigen::MatrixXd, 2> schur;
  bool definite[2] = {false, false};
  on_each_side([&](int s) {
    Side& side = sides_[at(s)];
    for (std::size_t k = 0; k < side.source.size(); ++k)
      side.matrix.value[k] = m.value[at(side.source[k])];
    definite[s] = side.factor.factorize(side.matrix);
    if (!definite[s]) return;
    side.schur_factor = side.factor.trailing_block(static_cast<int>(separator_.size()));
    schur[at(s)] = schur_on_separator(side);
  });
  if (!definite[0] || !definite[1]) return false;

  // A_SS − C₀'A₀⁻¹C₀ − C₁'A₁⁻¹C₁ = L₀ₛL₀ₛ' + L₁ₛL₁ₛ' − A_SS.
  complement_factor_ = schur[0] + schur[1];
  for (const Entry& e : separator_entries_)
    complement_factor_(e.row, e.col) -= m.value[at(e.source)];
  const int size = static_cast<int>(separator_.size());
  int info = 0;
  dpotrf_("L", &size, complement_factor_.data(), &size, &info, 1);
  return info == 0;
}

// Block elimination: each side's forward solve yields C'A⁻¹b (as −Lₛ times its tail), S is
// solved densely, and each side's backward solve, its tail set to Lₛ'x_S, yields A⁻¹(b − C x_S).
Eigen::VectorXd SubstructuredCholesky::solve(const Eigen::VectorXd& b) const {
  const int m = static_cast<int>(separator_.size());
  std::array<Eigen::VectorXd, 2> forward, coupling;
  on_each_side([&](int s) {
    const Side& side = sides_[at(s)];
    const int interior = static_cast<int>(side.interior.size());
    Eigen::VectorXd& v = forward[at(s)];
    v = Eigen::VectorXd::Zero(interior + m);
    for (int k = 0; k < interior; ++k) v[k] = b[side.interior[at(k)]];
    side.factor.apply(CholmodFactor::Step::permute, &v);
    side.factor.apply(CholmodFactor::Step::forward, &v);
    const Eigen::VectorXd c = side.schur_factor.triangularView<Eigen::Lower>() * v.tail(m);
    Eigen::VectorXd& out = coupling[at(s)];
    out.resize(m);
    for (int a = 0; a < m; ++a) out[side.tail_to_separator[at(a)]] = c[a];
  });
  Eigen::VectorXd separator_x(m);
  for (int j = 0; j < m; ++j) separator_x[j] = b[separator_[at(j)]];
  separator_x += coupling[0];
  separator_x += coupling[1];
  const int one = 1;
  int info = 0;
  dpotrs_("L", &m, &one, complement_factor_.data(), &m, separator_x.data(), &m, &info, 1);

  Eigen::VectorXd x(b.size());
  for (int j = 0; j < m; ++j) x[separator_[at(j)]] = separator_x[j];
  on_each_side([&](int s) {
    const Side& side = sides_[at(s)];
    const int interior = static_cast<int>(side.interior.size());
    Eigen::VectorXd v = forward[at(s)];
    Eigen::VectorXd tail(m);
    for (int a = 0; a < m; ++a) tail[a] = separator_x[side.tail_to_separator[at(a)]];
    v.tail(m) = side.schur_factor.triangularView<Eigen::Lower>().transpose() * tail;
    side.factor.apply(CholmodFactor::Step::backward, &v);
    side.factor.apply(CholmodFactor::Step::unpermute, &v);
    for (int k = 0; k < interior; ++k) x[side.interior[at(k)]] = v[k];
  });
  return x;
}

}  // namespace fabform
