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
//
// Gauss–Seidel is serial along its order, but any order of the lines is a Gauss–Seidel sweep.
// On a large level each direction's lines are taken in three runs: the first half, the second
// half but for the lines next to the first, and those last. The two halves share no coupling,
// so they are relaxed on two threads at once; the sweep is the same in any thread count, to the
// bit, and the backward sweep is still the forward one's exact reverse.
#include <array>
#include <cstddef>
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
  /// lines in the reverse order (backward). `a` the matrix the smoother was made from.
  void sweep(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             bool forward) const;

 private:
  struct Line {
    std::vector<int> unknowns;  // in order along the line
    BandedLdlt factor;  // of the line's block of a, shifted (line_gauss_seidel.cpp)
  };
  // The lines of one direction, in order across it. Forward, lines [0, seam) and
  // [seam_end, end) are relaxed at once, then [seam, seam_end): the lines either half's lines
  // next to it couple to, so that the halves share none (seam = seam_end = end where the level
  // is small or has too few lines).
  struct Family {
    std::vector<Line> lines;
    std::size_t seam = 0, seam_end = 0;
  };
  static Family family(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                       const std::vector<std::array<int, 2>>& place, int along, double shift);
  static void split(Family& family, int reach);
  static int factorise(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                       const std::vector<std::array<int, 2>>& place, int along, const std::vector<int>& line_of,
                       std::vector<int>& position, int id, double shift, Line& line);
  static void relax(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                    Eigen::VectorXd& x, const Line& line);
  static void relax_lines(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                          Eigen::VectorXd& x, const Family& family, std::size_t begin, std::size_t end,
                          bool forward);
  static void pass(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                   Eigen::VectorXd& x, const Family& family, bool forward);

  std::array<Family, 2> families_;  // lines along i, lines along j
  Eigen::Index rows_ = 0, nonzeros_ = 0;  // of the matrix they were made from
};

}  // namespace fabform
