// The doctest main, compiled once for every test executable (it is slow to compile).
// ARKSPH_FP_TRAPS=1 in the environment turns invalid operations, division by zero and overflow into
// SIGFPE (feenableexcept) before any test runs, so that a NaN or an infinity is caught where it is
// made; threads started later (OpenMP) inherit the setting. Scoped exceptions: FpTrapsOff in
// test_support.hpp.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>
#include <fenv.h>

#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  const char* traps = std::getenv("ARKSPH_FP_TRAPS");
  if (traps != nullptr && std::string(traps) == "1") feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
  doctest::Context context(argc, argv);
  return context.run();
}
