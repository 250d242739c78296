// The constrained projection at a free surface (projection/ConstrainedPressure.hpp with
// projection/free_surface.hpp), on the standing wave of cases/standing_wave at dx = 0.1:
//   - f(t, y) is a function of (t, y): the surface values and the Laplacian's defect, which depend
//     on p itself, are iterated to their fixed point inside each evaluation, so that an evaluation
//     at another state in between does not change it (with the terms lagged by one evaluation
//     instead, f at the same y differed by 0.053, as much as its largest rate);
//   - the temporal order that follows: Heun-Euler and Bogacki-Shampine within 0.3 of 2 and 3.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "io/scene_reader.hpp"
#include "run/setup.hpp"
#include "study/order_study.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
// The case's scene (cases/standing_wave/scene.toml) on a coarser lattice, under the constrained
// projection with KLU and a fixed Heun-Euler step.
const std::string kWave = std::string(ARKSPH_SOURCE_DIR) + "/cases/standing_wave/scene.toml";
const std::vector<std::string> kWaveSets = {"fluid.spacing=0.1",        "method.scheme=isph",
                                            "method.projection=constrained", "method.ppe_solver=klu",
                                            "time.end=0.8",             "output.every=0.8",
                                            "time.integrator=ARKODE_HEUN_EULER_2_1_2", "time.dt=0.04"};

// f(0, y): the right-hand side with the constrained pressure applied.
std::vector<double> constrained_rate(Model& model, const std::vector<double>& y) {
  std::vector<double> yd(y.size(), 0.0);
  model.rhs->eval(0.0, y.data(), yd.data());
  model.projection->constrain(y.data(), yd.data(), nullptr, nullptr);
  return yd;
}
}  // namespace

// Tolerance 1e-10 of the largest rate: the fixed point is iterated to 1e-12 of the largest p, and
// a direct solver (KLU) gives each iterate to round-off.
TEST_CASE("constrained projection at a free surface: f is a function of (t, y), not of the last evaluation") {
  const Scene scene = read_scene_file(kWave, kWaveSets);
  Model model = build_model(scene);
  std::vector<double> y(model.rhs->layout().size(), 0.0);
  model.rhs->initial_state(y.data());
  const std::vector<double> first = constrained_rate(model, y);
  // Another state in between: y + 0.2 f(y), the particles moved and the flow changed.
  std::vector<double> other = y;
  for (std::size_t i = 0; i < y.size(); ++i) other[i] += 0.2 * first[i];
  const std::vector<double> between = constrained_rate(model, other);
  const std::vector<double> again = constrained_rate(model, y);
  double rate = 0, moved = 0, differs = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    rate = std::max(rate, std::abs(first[i]));
    moved = std::max(moved, std::abs(between[i] - first[i]));
    differs = std::max(differs, std::abs(again[i] - first[i]));
  }
  MESSAGE("largest rate ", rate, ", change at the other state ", moved, ", at y again ", differs);
  REQUIRE(moved > 1e-6 * rate);  // the other state is another state
  CHECK(differs <= 1e-10 * rate);
}

// The order study's fit (velocity and pressure), as for the vortex of test_constrained_projection.cpp.
TEST_CASE("constrained projection at a free surface: Heun-Euler and Bogacki-Shampine keep their orders" *
          doctest::test_suite("long")) {
  OrderStudy study;
  study.scene = kWave;
  study.sets = kWaveSets;
  study.tables = {"ARKODE_HEUN_EULER_2_1_2", "ARKODE_BOGACKI_SHAMPINE_4_2_3"};
  study.dt = {0.08, 0.04, 0.02};
  study.reference_table = "ARKODE_DORMAND_PRINCE_7_4_5";
  study.reference_dt_divisor = 8;
  const auto fits = run_order_study(study, false);
  REQUIRE(fits.size() == 2);
  for (const auto& fit : fits) {
    MESSAGE(fit.table, ": velocity ", fit.observed_velocity, ", pressure ", fit.observed_pressure);
    CHECK(std::abs(fit.observed_velocity - fit.nominal) <= 0.3);
    CHECK(std::abs(fit.observed_pressure - fit.nominal) <= 0.3);
  }
}
