#pragma once
// Alternating line Gauss–Seidel, the lattice multigrid's smoother: the unknowns of each lattice
// line are solved together, the lines along i one after another and then those along j. A
// membrane of warp and weft springs is anisotropic: a node's move along a yarn is held by that
// yarn's springs a thousand times more strongly than by the tension across it, and on a curved
// fabric its normal by the tension alone. A smoother that relaxes one node at a time cannot
// smooth such an error across the yarns, so coarsening along both directions at once misses it;
// relaxing whole lines can, along whichever yarn is the stiff one (Trottenberg, Oosterlee &
// Schüller, Multigrid, §5.1). Reversing the order of the lines gives the adjoint sweep, so a
// forward sweep before the coarse correction and a backward one after keep the V-cycle
// symmetric positive definite, as conjugate gradients require.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "linalg/banded_ldlt.hpp"

namespace fabform {

class LineGaussSeidel {
 public:
  LineGaussSeidel() = default;
  /// `a` whole and symmetric, positive semidefinite; `place` each unknown's lattice point (i, j).
  LineGaussSeidel(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const std::vector<std::array<int, 2>>& place);

  /// One sweep on a x = b, updating x: the lines along i then along j (forward), or the same
  /// lines in the reverse order (backward).
  void sweep(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             bool forward) const;

 private:
  struct Line {
    std::vector<int> unknowns;  // in order along the line
    BandedLdlt factor;  // of the line's block of a, shifted (line_gauss_seidel.cpp)
  };
  using Family = std::vector<Line>;  // the lines of one direction, in order across it
  static Family family(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                       const std::vector<std::array<int, 2>>& place, int along, double shift);
  static void factorise(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                        const std::vector<std::array<int, 2>>& place, int along, const std::vector<int>& line_of,
                        std::vector<int>& position, int id, double shift, Line& line);
  static void relax(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                    Eigen::VectorXd& x, const Line& line);
  static void pass(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                   Eigen::VectorXd& x, const Family& family, bool forward);

  std::array<Family, 2> families_;  // lines along i, lines along j
};

}  // namespace fabform
