// `arksph study order`: the log-log fit, the acceptance study of five explicit tables (nominal
// orders 1-5) on the periodic Taylor-Green vortex, and the FLAG exit of the command.
#include <doctest/doctest.h>
#include <omp.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "core/errors.hpp"
#include "study/order_study.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
const std::string kStudies = std::string(ARKSPH_SOURCE_DIR) + "/cases/studies";
}

TEST_CASE("order study: the log-log least-squares slope of an exact power law is its exponent") {
  const std::vector<double> x = {0.1, 0.05, 0.02, 0.01};
  std::vector<double> y;
  for (double v : x) y.push_back(3.0 * std::pow(v, 2.5));
  CHECK(loglog_slope(x, y) == doctest::Approx(2.5).epsilon(1e-12));  // round-off of four logs
}

// The study of cases/studies/order_wcsph.toml, shortened to t = 0.02 (10 to 80 steps) to stay fast.
// The tolerance 0.3 is the project's acceptance threshold; it leaves room for the pre-asymptotic
// regime of three step sizes near the CFL limit (measured at t = 0.05: 1.195, 1.916, 3.053, 3.895,
// 5.120, and ARK324 3.0). Without the FSAL workaround ARK324 measures 2.0 (test_wcsph) and fails here.
TEST_CASE("order study: six explicit tables on the Taylor-Green vortex reach their nominal orders 1-5") {
  omp_set_num_threads(1);  // tiny system: threads only add overhead on a loaded 2-core machine
  const OrderStudy study = read_order_study(kStudies + "/order_wcsph.toml", {"time.end=0.02"});
  REQUIRE(study.tables.size() == 6);
  const auto fits = run_order_study(study, false);
  REQUIRE(fits.size() == 6);
  for (const auto& f : fits) {
    MESSAGE(f.table, " nominal ", f.nominal, " observed ", f.observed);
    CHECK(std::abs(f.observed - f.nominal) <= 0.3);
    CHECK_FALSE(f.flagged);
    for (std::size_t k = 1; k < f.points.size(); ++k)  // smaller step, smaller error
      CHECK(f.points[k].error < f.points[k - 1].error);
  }
  CHECK(fits.front().nominal == 1);
  CHECK(fits[4].nominal == 5);
  CHECK(fits[5].table == "ARKODE_ARK324L2SA_ERK_4_2_3");  // FSAL bug worked around: 3, not 2
}

// cases/studies/order_imex.toml shortened to t = 0.02: the ARKStep IMEX pairs with the viscous term
// implicit, Newton to a tight tolerance. Measured 3.02, 3.93, 3.88, 5.10, 5.04; tolerance 0.3 as
// above. With one Newton iteration per stage (time.imex_linear) every pair measures ~2 and fails.
TEST_CASE("order study: the five IMEX pairs (viscosity implicit) reach their nominal orders 3-5") {
  omp_set_num_threads(1);
  const OrderStudy study = read_order_study(kStudies + "/order_imex.toml", {"time.end=0.02"});
  REQUIRE(study.tables.size() == 5);
  const auto fits = run_order_study(study, false);
  REQUIRE(fits.size() == 5);
  for (const auto& f : fits) {
    MESSAGE(f.table, " nominal ", f.nominal, " observed ", f.observed);
    CHECK(std::abs(f.observed - f.nominal) <= 0.3);
    CHECK_FALSE(f.flagged);
  }
  CHECK(fits.front().table == "imex:ARK324L2SA");
  CHECK(fits.front().nominal == 3);
  CHECK(fits.back().nominal == 5);
}

// A tolerance no table can meet (1e-6) must flag every table and exit 4; the CSVs are written.
TEST_CASE("order study: a missed order is flagged in order_fit.csv and gives exit 4") {
  testing::ScratchDir scratch("order_flag");
  std::ofstream(scratch / "s.toml") << "[study]\nscene = \"" << kStudies << "/../sweeps/taylor_green_small.toml\"\n"
                                    << "set = [\"time.end=0.01\"]\ntables = [\"ARKODE_HEUN_EULER_2_1_2\"]\n"
                                    << "dt = [2e-3, 1e-3]\nreference_dt_divisor = 4\ntolerance = 1e-6\n";
  const std::string cmd = "OMP_NUM_THREADS=1 " + std::string(ARKSPH_BINARY) + " study order " + (scratch / "s.toml") +
                          " --out " + (scratch / "out") + " >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  CHECK(WEXITSTATUS(status) == 4);
  const std::string fit = testing::slurp(scratch / "out/order_fit.csv");
  CHECK(fit.find("ARKODE_HEUN_EULER_2_1_2,2,") != std::string::npos);
  CHECK(fit.find(",FLAG") != std::string::npos);
  CHECK(testing::slurp(scratch / "out/order_errors.csv").find("0.002") != std::string::npos);
}

TEST_CASE("order study: bad study files are refused naming the key") {
  testing::ScratchDir scratch("order_bad");
  const std::string scene = "scene = \"" + kStudies + "/../sweeps/taylor_green_small.toml\"\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[study]\n" + scene + "tables = [\"NO_SUCH_TABLE\"]\ndt = [1e-3, 5e-4]\n", "study.tables"},
      {"[study]\n" + scene + "tables = [\"ARKODE_HEUN_EULER_2_1_2\"]\ndt = [1e-3]\n", "study.dt"},
      {"[study]\n" + scene + "tables = [\"ARKODE_HEUN_EULER_2_1_2\"]\ndt = [1e-3, -1]\n", "study.dt"},
      {"[study]\n" + scene + "tables = [\"ARKODE_HEUN_EULER_2_1_2\"]\ndt = [1e-3, 5e-4]\nset = [\"method.kernel=x\"]\n",
       "method.kernel"},
      {"[study]\ntables = [\"ARKODE_HEUN_EULER_2_1_2\"]\ndt = [1e-3, 5e-4]\n", "study.scene"},
      {"[study]\n" + scene + "tables = [\"ARKODE_HEUN_EULER_2_1_2\"]\ndt = [1e-3, 5e-4]\n[dt_for]\nX = [1, 2]\n", "dt_for.X"},
  };
  for (const auto& [text, key] : cases) {
    CAPTURE(text);
    std::ofstream(scratch / "bad.toml") << text;
    try {
      read_order_study(scratch / "bad.toml", {});
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find(key) != std::string::npos);
    }
  }
}
