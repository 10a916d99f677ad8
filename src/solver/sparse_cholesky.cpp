#include "solver/sparse_cholesky.hpp"

#include <algorithm>
#include <vector>

#include <Eigen/CholmodSupport>

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

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::factorize(Eigen::SparseMatrix<double> lower) {
  lower.makeCompressed();  // the pattern comparison reads compressed storage
  if (!impl_->same_pattern(lower)) {
    impl_->llt.analyzePattern(lower);
    impl_->remember_pattern(lower);
  }
  impl_->llt.factorize(lower);
  return impl_->llt.info() == Eigen::Success;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const { return impl_->llt.solve(b); }

}  // namespace fabform
