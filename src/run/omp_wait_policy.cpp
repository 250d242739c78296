#include "run/omp_wait_policy.hpp"

#include <unistd.h>

#include <cstdlib>

namespace arksph {

void prefer_passive_omp_waiting(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
  setenv("GOMP_SPINCOUNT", kShortSpin, 0);  // a user's own value stays
  execv("/proc/self/exe", argv);
  // Still here: no /proc (or exec refused). Run on with libgomp's default policy.
}

}  // namespace arksph
