// OpenMP waiting threads: passive (sleep) unless the user chose otherwise.
//
// libgomp's default lets idle threads spin at every barrier. On a machine whose cores are busy with
// other work (CI runners, ctest -j2, a second run) a spinning thread holds a core the working thread
// needs, and a run becomes 10-30x slower: the default cavity scene to t = 0.1 with 2 threads took
// 8.9 s with spinning and 0.27 s with passive waiting at a load of 11 on 2 cores (bench/RESULTS.md).
// libgomp reads OMP_WAIT_POLICY once, when it is loaded, so the only way to change it for this
// process is to set it and re-execute the binary: done once, before anything else happens.
//
// Passive waiting with a short spin first: a thread that finishes its share of a parallel loop spins
// for GOMP_SPINCOUNT = 10,000 turns (libgomp's estimate: 0.1 ms) before it sleeps. A WCSPH f(t, y)
// at 50 x 50 runs its serial part (ghosts, equation of state) in about that time, so the second
// thread usually catches the next loop without a futex wake-up: the cavity to t = 2 on 2 threads
// took 2.2-2.4 s instead of 2.6-2.8 s. Oversubscribed (three 2-thread runs at once on 2 cores) the
// spin costs: 2.0-2.2 s against 1.6-1.7 s; batch children run on one thread, where it never spins.
#pragma once

namespace arksph {

inline constexpr const char* kShortSpin = "10000";

// If OMP_WAIT_POLICY is unset: sets it to PASSIVE (and GOMP_SPINCOUNT to kShortSpin unless set) and re-executes /proc/self/exe with argv (does not
// return on success; returns silently if the re-execution is impossible).
void prefer_passive_omp_waiting(char** argv);

}  // namespace arksph
