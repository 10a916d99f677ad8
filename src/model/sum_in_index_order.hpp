#pragma once
// A sum over items computed in parallel and added in index order: the same bits for any thread
// count, so a line search decides alike on 1 or 2 threads (a reduction's order would not).
#include <cstddef>
#include <numeric>
#include <vector>

#include "fabform/thread_count.hpp"

namespace fabform {

/// Σ part(i) for i = 0 … count − 1.
template <class Part>
double sum_in_index_order(std::ptrdiff_t count, const Part& part) {
  std::vector<double> parts(static_cast<std::size_t>(count), 0.0);
#pragma omp parallel for schedule(static) if (count >= kMinParallelItems)
  for (std::ptrdiff_t i = 0; i < count; ++i) parts[static_cast<std::size_t>(i)] = part(i);
  return std::accumulate(parts.begin(), parts.end(), 0.0);
}

}  // namespace fabform
