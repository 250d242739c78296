// OpenMP waiting threads: passive (sleep) unless the user chose otherwise.
//
// libgomp's default lets idle threads spin at every barrier. On a machine whose cores are busy with
// other work (CI runners, ctest -j2, a second run) a spinning thread holds a core the working thread
// needs, and a run becomes 10-30x slower: the default cavity scene to t = 0.1 with 2 threads took
// 8.9 s with spinning and 0.27 s with passive waiting at a load of 11 on 2 cores (bench/README.md).
// libgomp reads OMP_WAIT_POLICY once, when it is loaded, so the only way to change it for this
// process is to set it and re-execute the binary: done once, before anything else happens.
#pragma once

namespace arksph {

// If OMP_WAIT_POLICY is unset: sets it to PASSIVE and re-executes /proc/self/exe with argv (does not
// return on success; returns silently if the re-execution is impossible).
void prefer_passive_omp_waiting(char** argv);

}  // namespace arksph
