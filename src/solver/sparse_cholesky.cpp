#include "solver/sparse_cholesky.hpp"

#include <algorithm>
#include <vector>

#include <Eigen/CholmodSupport>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace fabform {

struct SparseCholesky::Impl {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  std::vector<int> outer, inner;  // the pattern analysed, to know when to analyse again
  bool analysed = false;

  // A matrix that is not positive definite is an expected outcome (the caller regularises
  // and retries), not something for CHOLMOD to print.
  Impl() { llt.cholmod().print = 0; }

  bool same_pattern(const Eigen::SparseMatrix<double>& m) const {
    return analysed && m.outerSize() + 1 == static_cast<Eigen::Index>(outer.size()) &&
           std::equal(outer.begin(), outer.end(), m.outerIndexPtr()) &&
           static_cast<Eigen::Index>(inner.size()) == m.nonZeros() &&
           std::equal(inner.begin(), inner.end(), m.innerIndexPtr());
  }
  void remember_pattern(const Eigen::SparseMatrix<double>& m) {
    outer.assign(m.outerIndexPtr(), m.outerIndexPtr() + m.outerSize() + 1);
    inner.assign(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros());
    analysed = true;
  }
};

namespace {

// CHOLMOD 3 runs small loops on a fixed team of 4 OpenMP threads (CHOLMOD_OMP_NUM_THREADS, fixed
// when Debian built it) whatever the machine and the thread setting; on 2 cores their wake-ups
// cost more than the loops (measured: 1e6 futex calls in a 10k-node dome). With no active
// parallel level allowed, those loops run on the caller; the dense kernels keep OpenBLAS's own
// threads, which follow the thread setting. Called from serial code only, as the setting is global.
template <class Work>
void without_cholmod_team(Work&& work) {
#ifdef _OPENMP
  struct Levels {
    const int saved = omp_get_max_active_levels();
    Levels() { omp_set_max_active_levels(0); }
    ~Levels() { omp_set_max_active_levels(saved); }
  } serial_only;
#endif
  work();
}

}  // namespace

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::factorize(Eigen::SparseMatrix<double> lower) {
  lower.makeCompressed();  // the pattern comparison reads compressed storage
  without_cholmod_team([&] {
    if (!impl_->same_pattern(lower)) {
      impl_->llt.analyzePattern(lower);
      impl_->remember_pattern(lower);
    }
    impl_->llt.factorize(lower);
  });
  return impl_->llt.info() == Eigen::Success;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x;
  without_cholmod_team([&] { x = impl_->llt.solve(b); });
  return x;
}

}  // namespace fabform
