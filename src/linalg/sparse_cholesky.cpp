#include "linalg/sparse_cholesky.hpp"

#include <algorithm>
#include <optional>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "linalg/cholmod_factor.hpp"
#include "linalg/substructured_cholesky.hpp"

namespace fabform {

struct SparseCholesky::Impl {
  int min_split_unknowns = SubstructuredCholesky::kMinUnknowns;
  LowerCsc matrix;  // the last matrix given; its pattern is the one analysed
  bool analysed = false;
  std::unique_ptr<SubstructuredCholesky> split;  // when the pattern splits usefully
  CholmodFactor whole;                           // otherwise

  bool same_pattern(const Eigen::SparseMatrix<double>& m) const {
    return analysed && m.rows() == matrix.n &&
           std::equal(matrix.start.begin(), matrix.start.end(), m.outerIndexPtr()) &&
           static_cast<Eigen::Index>(matrix.row.size()) == m.nonZeros() &&
           std::equal(matrix.row.begin(), matrix.row.end(), m.innerIndexPtr());
  }
  // The values, and the pattern only when it is new (within a solve it never is).
  void take(const Eigen::SparseMatrix<double>& m, bool new_pattern) {
    if (new_pattern) {
      matrix.n = static_cast<int>(m.rows());
      matrix.start.assign(m.outerIndexPtr(), m.outerIndexPtr() + m.outerSize() + 1);
      matrix.row.assign(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros());
    }
    matrix.value.assign(m.valuePtr(), m.valuePtr() + m.nonZeros());
  }
};

namespace {

// CHOLMOD 3 runs small loops on a fixed team of 4 OpenMP threads (CHOLMOD_OMP_NUM_THREADS, fixed
// when Debian built it) whatever the machine and the thread setting; on 2 cores their wake-ups
// cost more than the loops (measured: 1e6 futex calls in a 10k-node dome). Those loops stay on
// their caller when no parallel level is left for them: none for a matrix factorised whole, one
// (the split's two sides, on two threads) for a split one. Called from serial code only, as the
// setting is global.
template <class Work>
void without_cholmod_team(bool split, Work&& work) {
#ifdef _OPENMP
  struct Levels {
    const int saved = omp_get_max_active_levels();
    explicit Levels(int levels) { omp_set_max_active_levels(levels); }
    ~Levels() { omp_set_max_active_levels(saved); }
  } allowed(split && omp_get_max_threads() > 1 ? 1 : 0);
#endif
  work();
}

}  // namespace

SparseCholesky::SparseCholesky(int min_split_unknowns) : impl_(std::make_unique<Impl>()) {
  impl_->min_split_unknowns = min_split_unknowns;
}
SparseCholesky::SparseCholesky() : SparseCholesky(SubstructuredCholesky::kMinUnknowns) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::factorize(const Eigen::SparseMatrix<double>& given) {
  // The pattern comparison and the copy read compressed storage; an assembled matrix has it.
  std::optional<Eigen::SparseMatrix<double>> compressed;
  if (!given.isCompressed()) compressed.emplace(given).makeCompressed();
  const Eigen::SparseMatrix<double>& lower = compressed ? *compressed : given;
  Impl& impl = *impl_;
  const bool analyse = !impl.same_pattern(lower);
  impl.take(lower, analyse);
  if (analyse)
    without_cholmod_team(false, [&] {
      impl.split = SubstructuredCholesky::split(impl.matrix, impl.min_split_unknowns);
      if (!impl.split) impl.whole.analyse(impl.matrix);
      impl.analysed = true;
    });
  bool definite = false;
  without_cholmod_team(impl.split != nullptr, [&] {
    definite = impl.split ? impl.split->factorize(impl.matrix) : impl.whole.factorize(impl.matrix);
  });
  return definite;
}

bool SparseCholesky::split() const { return impl_->split != nullptr; }

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  without_cholmod_team(impl_->split != nullptr, [&] {
    if (impl_->split) x = impl_->split->solve(b);
    else impl_->whole.solve(&x);
  });
  return x;
}

}  // namespace fabform
