// The doctest main of the MPI tests (tests/CMakeLists.txt runs it under mpirun with 1, 2 and 3
// processes). Every rank runs every test case in the same order, so the collective calls inside the
// cases match. Ranks other than 0 report failures only. The exit code is the largest over the ranks,
// so a check that fails on one rank fails the run. ARKSPH_FP_TRAPS=1 traps floating-point errors as
// in tests/doctest_main.cpp.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>
#include <fenv.h>

#include <cstdlib>
#include <string>

#include "parallel/communicator.hpp"

int main(int argc, char** argv) {
  arksph::parallel::MpiSession session(&argc, &argv);
  const char* traps = std::getenv("ARKSPH_FP_TRAPS");
  if (traps != nullptr && std::string(traps) == "1") feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
  const arksph::parallel::Communicator world;
  doctest::Context context(argc, argv);
  if (world.rank() != 0) context.setOption("minimal", true);
  const int status = context.run();
  return static_cast<int>(world.max(static_cast<std::int64_t>(status)));
}
