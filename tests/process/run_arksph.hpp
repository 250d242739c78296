// Running the arksph binary from a test.
#pragma once
#include <sys/wait.h>

#include <cstdlib>
#include <string>

namespace arksph::testing {

// Runs the binary with `args`; returns its exit code (-1 if it did not exit normally). stdout and
// stderr go to `log` (appended). One OpenMP thread: these runs are tiny, and spinning threads on a
// loaded machine made them 50 times slower (results do not depend on the thread count).
inline int run_arksph(const std::string& args, const std::string& log) {
  const std::string cmd = "OMP_NUM_THREADS=1 " + std::string(ARKSPH_BINARY) + " " + args + " >>" + log + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace arksph::testing
