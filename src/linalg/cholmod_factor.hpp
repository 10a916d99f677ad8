#pragma once
// CHOLMOD, wrapped once: its workspace and one supernodal LL' factor, owned here. A matrix
// that is not positive definite is a result (false); CHOLMOD's failures (memory, a METIS
// limit) become std::runtime_error.
#include <memory>
#include <vector>

#include <Eigen/Core>

namespace fabform {

/// The lower triangle of a symmetric matrix in compressed columns, CHOLMOD's input layout:
/// rows ascending within each column, none above the diagonal.
struct LowerCsc {
  int n = 0;
  std::vector<int> start{0};  // n + 1 column starts
  std::vector<int> row;
  std::vector<double> value;
};

/// METIS's vertex bisection of the matrix's graph: per unknown 0 or 1 for the two sides, 2 for
/// the separator between them.
std::vector<int> vertex_bisection(const LowerCsc& pattern);

class CholmodFactor {
 public:
  CholmodFactor();
  ~CholmodFactor();
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  /// How analyse orders: CHOLMOD's own choice (AMD, or METIS when AMD fills in much), or
  /// CHOLMOD's nested dissection (METIS's bisections, constrained AMD within).
  enum class Ordering { automatic, nested_dissection };
  /// Orders the pattern of `m` and allocates the factor.
  void analyse(const LowerCsc& m, Ordering ordering = Ordering::automatic);
  /// The same in the order `given` (row k of the factor is row given[k]), its elimination tree
  /// postordered, which can only reorder columns that `given` leaves independent.
  void analyse_in_order(const LowerCsc& m, const std::vector<int>& given);
  /// False when the matrix (the pattern analysed, these values) is not positive definite.
  bool factorize(const LowerCsc& m);

  /// Row k of the factor is row order()[k] of the matrix.
  std::vector<int> order() const;

  /// x ← A⁻¹x, for the matrix last factorised.
  void solve(Eigen::VectorXd* x) const;
  /// The steps of that solve, L L' = P A P': permute (x ← P x), forward (x ← L⁻¹x),
  /// backward (x ← L'⁻¹x) and unpermute (x ← P'x).
  enum class Step { permute, forward, backward, unpermute };
  void apply(Step step, Eigen::VectorXd* x) const;

  /// The factor's last `tail` rows and columns, dense (zero above the diagonal).
  Eigen::MatrixXd trailing_block(int tail) const;

 private:
  void analyse(const LowerCsc& m, Ordering ordering, const std::vector<int>* given);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fabform
