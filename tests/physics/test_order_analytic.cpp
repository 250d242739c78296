// The order study's analytic-error mode (reference = "analytic"): on a flow whose analytic solution
// is also the exact solution of the particle equations (uniform oscillating flow, zero spatial error)
// the observed orders are the nominal ones; a wrong analytic field is caught; bad keys are refused.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "study/order_study.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
const std::string kAnalyticStudies = std::string(ARKSPH_SOURCE_DIR) + "/cases/studies";
}

TEST_CASE("order study in analytic mode: uniform oscillating flow gives the nominal orders 1-5") {
  const OrderStudy study = read_order_study(kAnalyticStudies + "/order_analytic.toml", {});
  REQUIRE(study.reference == "analytic");
  const auto fits = run_order_study(study, false);
  REQUIRE(fits.size() == 5);
  for (const auto& f : fits) {
    CAPTURE(f.table);
    // The study's tolerance (0.3, as the fine-step mode); measured 1.005, 2.000, 3.001, 4.000, 5.096.
    CHECK(std::abs(f.observed - f.nominal) <= 0.3);
    CHECK_FALSE(f.flagged);
  }
}

TEST_CASE("order study in analytic mode: a wrong analytic field levels the error off and is flagged") {
  testing::ScratchDir scratch("order_analytic_wrong");
  // u_exact off by 1e-3 (sin(10t)/10 + 1e-3): the error tends to 1e-3 instead of 0, the slope to ~0.
  std::ofstream(scratch / "wrong.toml")
      << "[study]\nscene = \"" << kAnalyticStudies << "/../sweeps/taylor_green_small.toml\"\n"
      << "set = [\"time.end=0.5\", \"initial.velocity=[\\\"0\\\", \\\"0\\\"]\", \"fluid.body_force=[\\\"cos(10*t)\\\", \\\"0\\\"]\"]\n"
      << "tables = [\"ARKODE_HEUN_EULER_2_1_2\"]\ndt = [4e-3, 2e-3, 1e-3]\nreference = \"analytic\"\n"
      << "analytic_velocity = [\"sin(10*t)/10 + 1e-3\", \"0\"]\n";
  const auto fits = run_order_study(read_order_study(scratch / "wrong.toml", {}), false);
  REQUIRE(fits.size() == 1);
  CHECK(fits[0].observed < 0.5);
  CHECK(fits[0].flagged);
}

TEST_CASE("order study in analytic mode: bad reference keys are refused naming the key") {
  testing::ScratchDir scratch("order_analytic_bad");
  const std::string head = "[study]\nscene = \"" + kAnalyticStudies + "/../sweeps/taylor_green_small.toml\"\n" +
                           "tables = [\"ARKODE_HEUN_EULER_2_1_2\"]\ndt = [1e-3, 5e-4]\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + "reference = \"exact\"\n", "study.reference"},
      {head + "reference = \"analytic\"\n", "study.analytic_velocity"},
      {head + "reference = \"analytic\"\nanalytic_velocity = [\"x\"]\n", "study.analytic_velocity"},
      {head + "reference = \"analytic\"\nanalytic_velocity = [\"x +\", \"0\"]\n", "study.analytic_velocity"},
      {head + "analytic_velocity = [\"x\", \"0\"]\n", "study.analytic_velocity"},
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
