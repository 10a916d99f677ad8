#pragma once
// A sparse Cholesky that runs on two threads: the matrix is split by a vertex separator S
// (METIS, through CHOLMOD) into two sides that share nothing but S. Each side with S is
// factorised by CHOLMOD on its own thread, S ordered last, so that the factor's trailing block
// Lₛ holds the side's Schur complement on S: A_SS − C'A⁻¹C = LₛLₛ'. The whole matrix's complement
// on S is then the sum of the two minus A_SS, dense, factorised by LAPACK.
// The arithmetic does not depend on the thread count: one thread does the two sides in turn.
#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "solver/cholmod_factor.hpp"

namespace fabform {

class SubstructuredCholesky {
 public:
  /// The split of `pattern`, or null when it does not split usefully (too small, a side
  /// empty, a separator too large for its dense complement).
  static std::unique_ptr<SubstructuredCholesky> split(const LowerCsc& pattern);

  /// Factorises `m`, whose pattern is the one split; false when it is not positive definite.
  bool factorize(const LowerCsc& m);
  /// x with A x = b for the matrix last factorised successfully.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  /// The separator's unknowns, ascending.
  const std::vector<int>& separator() const { return separator_; }

  /// Below this many unknowns a plain factorisation is cheaper than the split's overhead.
  static constexpr int kMinUnknowns = 2000;
  /// S's complement is dense: at most this many unknowns (72 MB a copy at the limit).
  static constexpr int kMaxSeparator = 3000;

 private:
  struct Side {
    std::vector<int> interior;  // unknowns of the whole matrix, in the side's order; S follows
    LowerCsc matrix;            // the side with S, S last
    std::vector<int> source;    // for each entry of `matrix`, its index in the whole matrix's
    CholmodFactor factor;
    std::vector<int> tail_to_separator;  // factor row n_interior + a is separator unknown [a]
    Eigen::MatrixXd schur_factor;        // Lₛ, in the factor's order of S
  };
  struct Entry {
    int row, col, source;  // a lower entry of A_SS, in separator indices
  };

  SubstructuredCholesky() = default;
  bool build_side(const LowerCsc& pattern, const std::vector<int>& local, Side* side) const;
  Eigen::MatrixXd schur_on_separator(const Side& side) const;

  std::array<Side, 2> sides_;
  std::vector<int> separator_;  // unknowns of the whole matrix
  std::vector<Entry> separator_entries_;
  Eigen::MatrixXd complement_factor_;  // Cholesky factor of the whole matrix's complement on S
};

}  // namespace fabform
