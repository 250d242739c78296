// The CPU time of this process: user + system, all threads (getrusage). Szewc et al. compare
// schemes by CPU time (their Fig. 10); unlike the wall time it does not count time the process
// spent waiting for a core or stopped, so figures from a shared machine stay comparable.
#pragma once

namespace arksph {

double process_cpu_seconds();

}  // namespace arksph
