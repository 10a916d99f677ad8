#pragma once
// How many threads a solve may use: OpenMP's loops over nodes and springs follow it. Every
// solver gives the same bits for any thread count: loops write per node or per spring and sum
// in a fixed order; OpenBLAS under CHOLMOD runs on one thread and CHOLMOD's own OpenMP loops on
// the calling thread (sparse_cholesky.cpp).

namespace fabform {

/// Loops over fewer items than this run on one thread: waking the others costs more than the
/// work (and OpenMP's spinning threads steal cores from other processes on a loaded machine).
constexpr int kMinParallelItems = 8192;

/// Sets the thread count of the parallel loops (n ≥ 1).
void use_threads(int n);

/// The thread count the parallel loops use now (OpenMP's default, the cores, until use_threads).
int threads_in_use();

}  // namespace fabform
