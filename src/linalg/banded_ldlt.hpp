#pragma once
// LDLᵀ of a symmetric banded matrix, stored by rows of its lower band: the line smoother's
// blocks (line_gauss_seidel.hpp) couple each unknown only to those a few places along its line,
// so their factors fill only the band. Stored densely within it, a factor is one array with no
// index arrays, and factorising it allocates once: lines are factorised on every thread, where
// Eigen's simplicial LDLᵀ spent its time in many small allocations and a copy of the block to
// permute it. The band is stored whole, so it suits blocks whose every row reaches about as far.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace fabform {

class BandedLdlt {
 public:
  BandedLdlt() = default;
  /// An empty matrix of `size` rows with `bandwidth` places below the diagonal; every entry zero.
  BandedLdlt(int size, int bandwidth);

  /// Entry (row, column) of the lower band, column ≤ row ≤ column + bandwidth; before factorise.
  double& at(int row, int column);

  /// Factorises in place. False where a pivot is zero (as Eigen's LDLᵀ, negative pivots are
  /// taken: the factors are exact for any symmetric matrix without a zero leading minor).
  bool factorise();

  /// Overwrites b with A⁻¹ b; after a successful factorise.
  void solve_in_place(Eigen::Ref<Eigen::VectorXd> b) const;

  int bandwidth() const { return bandwidth_; }

 private:
  // Row r's first place holding a column of the matrix (the top rows' bands start before it).
  std::size_t first_place(int r) const;

  int size_ = 0;
  int bandwidth_ = 0;
  std::vector<double> lower_;  // row r's places r − bandwidth ... r − 1, then D in diagonal_
  std::vector<double> diagonal_;
};

}  // namespace fabform
