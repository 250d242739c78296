// The number of OpenMP threads, bounded.
//
// libgomp starts OMP_NUM_THREADS threads at the first parallel region, whatever the machine: from
// about 1,000 it fails to create them and ends the process with its own message, at 100,000 it
// crashes. A run gains nothing from more threads than processors (its loops are memory-bound), so
// the count is capped at kThreadsPerProcessor x the processors available, with one line on stderr.
#pragma once

namespace arksph {

inline constexpr int kThreadsPerProcessor = 4;

// Caps omp_get_max_threads() before the first parallel region (a no-op without OpenMP).
void bound_omp_threads();

}  // namespace arksph
