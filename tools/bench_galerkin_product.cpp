// Benchmark: the multigrid's Galerkin product PᵀAP (src/linalg/galerkin_product.cpp) on one
// thread and on two, in the same run, on a lattice of N × N points with three unknowns each and
// a full 3 × 3 block between every point and its eight neighbours (what the dome's Newton matrix
// holds where the fabric is free), P the lattice's bilinear interpolation. Prints the fastest of
// the repeats on each thread count and their ratio (the threads issue's target is 1.6 × on two).
//   build/fabform_bench_galerkin [N] [REPEATS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fabform/thread_count.hpp"
#include "linalg/galerkin_product.hpp"
#include "linalg/lattice_prolongation.hpp"
#include "linalg/sparse_transpose.hpp"

namespace {

using fabform::RowMatrix;

// The lattice's matrix: diagonally dominant, every neighbour coupled in all three directions.
RowMatrix lattice_matrix(int n) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a)
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int ii = i + di, jj = j + dj;
            if (ii < 0 || jj < 0 || ii >= n || jj >= n) continue;
            for (int b = 0; b < 3; ++b)
              entries.emplace_back(3 * (i + n * j) + a, 3 * (ii + n * jj) + b, di == 0 && dj == 0 && a == b ? 10.0 : -0.1);
          }
  RowMatrix m(3 * n * n, 3 * n * n);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

double fastest_seconds(const RowMatrix& r, const RowMatrix& a, const RowMatrix& p, int repeats) {
  double best = 1e300;
  for (int k = 0; k < repeats; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const RowMatrix coarse = fabform::galerkin_product(r, a, p);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (coarse.nonZeros() == 0) std::abort();  // kept, so the product is not optimised away
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 401;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
  if (n < 2 || repeats < 1) {
    std::fprintf(stderr, "usage: fabform_bench_galerkin [N >= 2] [REPEATS >= 1]\n");
    return 2;
  }
  const RowMatrix a = lattice_matrix(n);
  const RowMatrix p = fabform::lattice_prolongation({n, n});
  const RowMatrix r = fabform::transposed(p);
  fabform::use_threads(1);
  const double one = fastest_seconds(r, a, p, repeats);
  fabform::use_threads(2);
  const double two = fastest_seconds(r, a, p, repeats);
  std::printf("Galerkin product, %d x %d points (%ld unknowns, %ld entries), fastest of %d\n", n, n,
              static_cast<long>(a.rows()), static_cast<long>(a.nonZeros()), repeats);
  std::printf("one thread  %.4f s\ntwo threads %.4f s\nratio       %.2f\n", one, two, one / two);
  return 0;
}
