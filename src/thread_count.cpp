#include "fabform/thread_count.hpp"

#include <dlfcn.h>
#include <omp.h>

namespace fabform {

void use_threads(int n) {
  omp_set_num_threads(n);
  // OpenBLAS keeps its own thread pool, sized from the cores unless told otherwise. It stays
  // at one thread: its threaded kernels split sums by thread count, so a factorisation's last
  // bits, and from them Newton's contact decisions, would depend on it; and on these grids'
  // supernodes it gained nothing measurable (newton N=401: 1.01x on 2 threads). The BLAS is
  // whichever Debian's alternatives chose, so OpenBLAS's setter is looked up, not linked.
  using Setter = void (*)(int);
  if (auto set = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
    set(1);
}

int threads_in_use() { return omp_get_max_threads(); }

}  // namespace fabform
