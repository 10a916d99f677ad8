#pragma once
// How many threads a solve may use: OpenMP's loops over nodes and springs and the OpenBLAS
// threads under CHOLMOD's dense kernels follow one setting (CHOLMOD's own OpenMP loops run on
// the calling thread: see sparse_cholesky.cpp).

namespace fabform {

/// Loops over fewer items than this run on one thread: waking the others costs more than the
/// work (and OpenMP's spinning threads steal cores from other processes on a loaded machine).
constexpr int kMinParallelItems = 8192;

/// Sets the thread count of every parallel part (n ≥ 1).
void use_threads(int n);

}  // namespace fabform
