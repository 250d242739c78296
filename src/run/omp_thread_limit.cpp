#include "run/omp_thread_limit.hpp"

#include "run/launcher_ranks.hpp"

#include <cstdio>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace arksph {

void bound_omp_threads() {
#ifdef _OPENMP
  const int processors = static_cast<int>(std::thread::hardware_concurrency());
  const int cap = kThreadsPerProcessor * (processors > 0 ? processors : 1);
  const int asked = omp_get_max_threads();
  if (asked <= cap) return;
  omp_set_num_threads(cap);
  if (launcher_ranks_from_environment().rank != 0) return;  // said once, by rank 0 of a launch
  std::fprintf(stderr, "arksph: OMP_NUM_THREADS asks for %d threads on %d processors; using %d (at most %d per processor)\n",
               asked, processors, cap, kThreadsPerProcessor);
#endif
}

}  // namespace arksph
