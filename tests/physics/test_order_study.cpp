// `arksph study order`: the acceptance studies of six explicit tables (nominal orders 1-5) and five
// IMEX pairs on the periodic Taylor-Green vortex.
#include <doctest/doctest.h>
#include <omp.h>

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

// The study of cases/studies/order_wcsph.toml, shortened to t = 0.02 (10 to 80 steps) to stay fast.
// The tolerance 0.3 is the acceptance threshold; it leaves room for the pre-asymptotic
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
