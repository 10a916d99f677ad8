#include "linalg/sparse_transpose.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "fabform/thread_count.hpp"

namespace fabform {

namespace {

// A compressed sparse matrix's arrays, by outer vector (rows of a row-major matrix, columns of
// a column-major one).
struct Outers {
  Eigen::Index count;
  const int* start;  // count + 1
  const int* inner;
  const double* value;
};

template <class Matrix>
Outers outers_of(const Matrix& m) {
  return {m.outerSize(), m.outerIndexPtr(), m.innerIndexPtr(), m.valuePtr()};
}

// Thread t's outer vectors, [band[t], band[t + 1]): about as many entries each.
std::vector<Eigen::Index> bands(const Outers& m, int threads) {
  std::vector<Eigen::Index> band(static_cast<std::size_t>(threads) + 1, m.count);
  band[0] = 0;
  const long long entries = m.start[m.count];
  Eigen::Index o = 0;
  for (int t = 1; t < threads; ++t) {
    while (o < m.count && m.start[o] < entries * t / threads) ++o;
    band[static_cast<std::size_t>(t)] = o;
  }
  return band;
}

// The rows × columns matrix whose row r holds, in this order, entry (o, r) of `m` at column o
// for each o with crossed(o, r) (o increasing), then entry (r, i) of `m` at column i for each i
// with kept(r, i) (as `m` lists them). Each thread scatters its band's entries to places
// counted for it beforehand, so the result does not depend on the threads.
template <class Crossed, class Kept>
RowMatrix gathered(const Outers& m, Eigen::Index rows, Eigen::Index columns, Crossed crossed, Kept kept) {
  // Each thread holds a count per row: no more threads than entries a row, so that the counts
  // never outnumber the entries.
  const long long entries = m.start[m.count];
  const int threads = entries < kMinParallelItems || rows == 0
                          ? 1
                          : static_cast<int>(std::clamp<long long>(entries / rows, 1, threads_in_use()));
  const std::vector<Eigen::Index> band = bands(m, threads);
  // Per thread and row: first its entries crossed there, then where the next one goes.
  std::vector<std::vector<int>> place(static_cast<std::size_t>(threads), std::vector<int>(static_cast<std::size_t>(rows), 0));
  std::vector<int> own(static_cast<std::size_t>(m.count), 0);  // per outer vector, its entries kept
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (int t = 0; t < threads; ++t) {
    std::vector<int>& count = place[static_cast<std::size_t>(t)];
    for (Eigen::Index o = band[static_cast<std::size_t>(t)]; o < band[static_cast<std::size_t>(t) + 1]; ++o)
      for (int p = m.start[o]; p < m.start[o + 1]; ++p) {
        if (crossed(o, m.inner[p])) ++count[static_cast<std::size_t>(m.inner[p])];
        if (kept(o, m.inner[p])) ++own[static_cast<std::size_t>(o)];
      }
  }
  RowMatrix out(rows, columns);
  long long at = 0;
  for (Eigen::Index r = 0; r < rows; ++r) {
    const auto row = static_cast<std::size_t>(r);
    out.outerIndexPtr()[r] = static_cast<int>(at);
    for (std::vector<int>& count : place) {
      const int crossing = count[row];
      count[row] = static_cast<int>(at);
      at += crossing;
    }
    if (r < m.count) at += own[row];
    if (at > std::numeric_limits<int>::max())
      throw std::length_error("sparse transpose: more entries than Eigen's int indices hold");
  }
  out.outerIndexPtr()[rows] = static_cast<int>(at);
  out.resizeNonZeros(static_cast<Eigen::Index>(at));
  int* inner = out.innerIndexPtr();
  double* value = out.valuePtr();
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (int t = 0; t < threads; ++t) {
    std::vector<int>& next = place[static_cast<std::size_t>(t)];
    for (Eigen::Index o = band[static_cast<std::size_t>(t)]; o < band[static_cast<std::size_t>(t) + 1]; ++o) {
      for (int p = m.start[o]; p < m.start[o + 1]; ++p)
        if (crossed(o, m.inner[p])) {
          const int q = next[static_cast<std::size_t>(m.inner[p])]++;
          inner[q] = static_cast<int>(o);
          value[q] = m.value[p];
        }
      if (own[static_cast<std::size_t>(o)] == 0) continue;
      int q = out.outerIndexPtr()[o + 1] - own[static_cast<std::size_t>(o)];  // after the row's crossed entries
      for (int p = m.start[o]; p < m.start[o + 1]; ++p)
        if (kept(o, m.inner[p])) {
          inner[q] = m.inner[p];
          value[q++] = m.value[p];
        }
    }
  }
  return out;
}

}  // namespace

RowMatrix transposed(const RowMatrix& a) {
  if (!a.isCompressed()) {
    RowMatrix compressed = a;
    compressed.makeCompressed();
    return transposed(compressed);
  }
  return gathered(
      outers_of(a), a.cols(), a.rows(), [](Eigen::Index, int) { return true; },
      [](Eigen::Index, int) { return false; });
}

RowMatrix whole_symmetric(const Eigen::SparseMatrix<double>& lower) {
  if (lower.rows() != lower.cols()) throw std::invalid_argument("whole_symmetric: the matrix is not square");
  if (!lower.isCompressed()) {
    Eigen::SparseMatrix<double> compressed = lower;
    compressed.makeCompressed();
    return whole_symmetric(compressed);
  }
  // Column o's entry in row i ≥ o is (i, o) of the whole, and for i > o also (o, i).
  return gathered(
      outers_of(lower), lower.rows(), lower.cols(), [](Eigen::Index o, int i) { return i >= o; },
      [](Eigen::Index o, int i) { return i > o; });
}

}  // namespace fabform
