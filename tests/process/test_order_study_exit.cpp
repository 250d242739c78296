// `arksph study order`, the real binary: a missed order is flagged and gives exit 4.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "test_support.hpp"

namespace {
const std::string kExitStudies = std::string(ARKSPH_SOURCE_DIR) + "/cases/studies";
}

// A tolerance no table can meet (1e-6) must flag every table and exit 4; the CSVs are written.
TEST_CASE("order study: a missed order is flagged in order_fit.csv and gives exit 4") {
  arksph::testing::ScratchDir scratch("order_flag");
  std::ofstream(scratch / "s.toml") << "[study]\nscene = \"" << kExitStudies << "/../sweeps/taylor_green_small.toml\"\n"
                                    << "set = [\"time.end=0.01\"]\ntables = [\"ARKODE_HEUN_EULER_2_1_2\"]\n"
                                    << "dt = [2e-3, 1e-3]\nreference_dt_divisor = 4\ntolerance = 1e-6\n";
  const std::string cmd = "OMP_NUM_THREADS=1 " + std::string(ARKSPH_BINARY) + " study order " + (scratch / "s.toml") +
                          " --out " + (scratch / "out") + " >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  CHECK(WEXITSTATUS(status) == 4);
  const std::string fit = arksph::testing::slurp(scratch / "out/order_fit.csv");
  CHECK(fit.find("ARKODE_HEUN_EULER_2_1_2,2,") != std::string::npos);
  CHECK(fit.find(",FLAG") != std::string::npos);
  CHECK(arksph::testing::slurp(scratch / "out/order_errors.csv").find("0.002") != std::string::npos);
}
