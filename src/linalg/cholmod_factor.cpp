#include "linalg/cholmod_factor.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <cholmod.h>

namespace fabform {
namespace {

// A view of `m` for CHOLMOD, which reads but does not write its input here.
cholmod_sparse view_of(const LowerCsc& m) {
  cholmod_sparse a{};
  a.nrow = a.ncol = static_cast<std::size_t>(m.n);
  a.nzmax = m.row.size();
  a.p = const_cast<int*>(m.start.data());
  a.i = const_cast<int*>(m.row.data());
  a.x = const_cast<double*>(m.value.data());
  a.stype = -1;  // the lower triangle of a symmetric matrix
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

cholmod_dense view_of(Eigen::VectorXd* x) {
  cholmod_dense d{};
  d.nrow = d.d = d.nzmax = static_cast<std::size_t>(x->size());
  d.ncol = 1;
  d.x = x->data();
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

}  // namespace

std::vector<int> vertex_bisection(const LowerCsc& pattern) {
  cholmod_common c{};
  cholmod_start(&c);
  c.print = 0;
  cholmod_sparse a = view_of(pattern);
  std::vector<int> partition(static_cast<std::size_t>(pattern.n));
  // compress: a node's unknowns share their pattern, and METIS then partitions nodes.
  cholmod_bisect(&a, nullptr, 0, 1, partition.data(), &c);
  const int status = c.status;
  cholmod_finish(&c);
  if (status < CHOLMOD_OK)
    throw std::runtime_error("CHOLMOD bisection failed (status " + std::to_string(status) + ")");
  return partition;
}

struct CholmodFactor::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;

  Impl() {
    cholmod_start(&common);
    common.print = 0;                          // not being positive definite is our result
    common.supernodal = CHOLMOD_SUPERNODAL;    // dense fronts; trailing_block reads them
    common.quick_return_if_not_posdef = 1;
  }
  ~Impl() {
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  // x ← the solution of CHOLMOD's `system` with right-hand side x.
  void solve(int system, Eigen::VectorXd* x) {
    cholmod_dense b = view_of(x);
    cholmod_dense* solved = cholmod_solve(system, factor, &b, &common);
    check("solve");
    x->noalias() =
        Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(solved->x), x->size());
    cholmod_free_dense(&solved, &common);
  }
  void check(const char* what) const {
    if (common.status < CHOLMOD_OK)
      throw std::runtime_error(std::string("CHOLMOD ") + what + " failed (status " +
                               std::to_string(common.status) + ")");
  }
};

CholmodFactor::CholmodFactor() : impl_(std::make_unique<Impl>()) {}
CholmodFactor::~CholmodFactor() = default;

void CholmodFactor::analyse(const LowerCsc& m, Ordering ordering) { analyse(m, ordering, nullptr); }

void CholmodFactor::analyse_in_order(const LowerCsc& m, const std::vector<int>& given) {
  analyse(m, Ordering::automatic, &given);
}

void CholmodFactor::analyse(const LowerCsc& m, Ordering ordering, const std::vector<int>* given) {
  cholmod_free_factor(&impl_->factor, &impl_->common);
  cholmod_sparse a = view_of(m);
  cholmod_common& c = impl_->common;
  const int saved_methods = c.nmethods, saved_ordering = c.method[0].ordering;
  if (given) {
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_GIVEN;
  } else if (ordering == Ordering::nested_dissection) {
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_NESDIS;
  }
  impl_->factor = cholmod_analyze_p(&a, given ? const_cast<int*>(given->data()) : nullptr,
                                    nullptr, 0, &c);
  c.nmethods = saved_methods;
  c.method[0].ordering = saved_ordering;
  impl_->check("analysis");
}

bool CholmodFactor::factorize(const LowerCsc& m) {
  cholmod_sparse a = view_of(m);
  cholmod_factorize(&a, impl_->factor, &impl_->common);
  impl_->check("factorisation");
  return impl_->common.status == CHOLMOD_OK && impl_->factor->minor == impl_->factor->n;
}

std::vector<int> CholmodFactor::order() const {
  const auto* perm = static_cast<const int*>(impl_->factor->Perm);
  return std::vector<int>(perm, perm + impl_->factor->n);
}

void CholmodFactor::solve(Eigen::VectorXd* x) const { impl_->solve(CHOLMOD_A, x); }

void CholmodFactor::apply(Step step, Eigen::VectorXd* x) const {
  static constexpr int kSystem[] = {CHOLMOD_P, CHOLMOD_L, CHOLMOD_Lt, CHOLMOD_Pt};
  impl_->solve(kSystem[static_cast<int>(step)], x);
}

// A supernode s holds columns super[s] .. super[s+1]−1, dense, column-major, one row per index
// in s[pi[s]] .. s[pi[s+1]−1] (its own columns first).
Eigen::MatrixXd CholmodFactor::trailing_block(int tail) const {
  const cholmod_factor& f = *impl_->factor;
  const int n = static_cast<int>(f.n), first = n - tail;
  const auto* super = static_cast<const int*>(f.super);
  const auto* pi = static_cast<const int*>(f.pi);
  const auto* px = static_cast<const int*>(f.px);
  const auto* rows = static_cast<const int*>(f.s);
  const auto* values = static_cast<const double*>(f.x);
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(tail, tail);
  for (std::size_t s = 0; s < f.nsuper; ++s) {
    const int height = pi[s + 1] - pi[s];
    for (int col = std::max(super[s], first); col < super[s + 1]; ++col) {
      const int c = col - super[s];
      for (int r = c; r < height; ++r)
        block(rows[pi[s] + r] - first, col - first) = values[px[s] + c * height + r];
    }
  }
  return block;
}

}  // namespace fabform
