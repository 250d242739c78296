// `arksph study order` without running a study: the log-log fit and the study file reader.
// The acceptance studies: physics/test_order_study.cpp; the command's FLAG exit:
// process/test_order_study_exit.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

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
