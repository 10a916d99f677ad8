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

#include "linalg/cholmod_factor.hpp"

namespace fabform {

class SubstructuredCholesky {
 public:
  /// The split of `pattern`, or null when it does not split usefully (fewer than
  /// `min_unknowns`, a side or the separator empty, a separator too large for its dense
  /// complement).
  static std::unique_ptr<SubstructuredCholesky> split(const LowerCsc& pattern,
                                                      int min_unknowns = kMinUnknowns);

  /// Factorises `m`, whose pattern is the one split; false when it is not positive definite.
  bool factorize(const LowerCsc& m);
  /// x with A x = b for the matrix last factorised successfully.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  /// The separator's unknowns, ascending.
  const std::vector<int>& separator() const { return separator_; }

  /// Below this many unknowns the whole matrix factorises about as fast on one thread as the split
  /// does (dome, newton to 1e-6 N, measured with this threshold lowered, one thread: N = 101,
  /// 31 000 unknowns, whole 1.03 s, split 1.67 s; N = 201, 120 000, whole 9.7 s, split 12.0 s;
  /// N = 401, 480 000, whole 93.2 s, split 90.9 s). On two threads the split takes 1.01 s,
  /// 6.0 s and 53.0 s; a threshold that followed the thread count would make the bits follow it.
  static constexpr int kMinUnknowns = 300000;
  /// S's complement is dense: at most this many unknowns (162 MB a copy at the limit; a
  /// 1000 × 1000 grid's separator has about 3000).
  static constexpr int kMaxSeparator = 4500;

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
