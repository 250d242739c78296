// The parts of the energy budget (diagnostics/energy_budget.hpp): the Tait equation of state's
// compressible energy e(rho) against its definition de/drho = p / rho^2, e(rho0) = 0, and the
// trapezoid sum of the viscous dissipation over the steps.
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "diagnostics/viscous_dissipation.hpp"
#include "rhs/pressure/tait_energy.hpp"

using namespace arksph;

namespace {
// The Tait pressure of rhs/pressure/EquationOfState_Tait.cpp.
double tait_pressure(double rho, double rho0, double c, double gamma, double background) {
  return c * c * rho0 / gamma * (std::pow(rho / rho0, gamma) - 1.0) + background;
}
}  // namespace

// Central differences of e with step 1e-5 rho0: truncation error ~ 1e-10 relative to p / rho^2 at
// these densities (e''' bounded), round-off ~ 1e-16 e / 1e-5; tolerance 1e-7 relative.
TEST_CASE("energy budget: the Tait energy vanishes at rho0 and its derivative is p / rho^2") {
  for (double gamma : {7.0, 1.4, 1.0})
    for (double background : {0.0, 2.5})
      for (double rho0 : {1.0, 1000.0}) {
        CAPTURE(gamma);
        CAPTURE(background);
        CAPTURE(rho0);
        const double c = 10;
        CHECK(tait_specific_energy(rho0, rho0, c, gamma, background) == 0.0);
        for (double x : {0.9, 0.99, 1.001, 1.05, 1.2}) {
          CAPTURE(x);
          const double rho = x * rho0, h = 1e-5 * rho0;
          const double de = (tait_specific_energy(rho + h, rho0, c, gamma, background) -
                             tait_specific_energy(rho - h, rho0, c, gamma, background)) / (2 * h);
          const double expected = tait_pressure(rho, rho0, c, gamma, background) / (rho * rho);
          CHECK(de == doctest::Approx(expected).epsilon(1e-7));
        }
      }
  // Near rho0 without background pressure: the acoustic energy c^2 delta^2 / 2, delta = rho / rho0 - 1,
  // up to a relative O(gamma delta) = 7e-4 at delta = 1e-4: tolerance 1e-3.
  const double delta = 1e-4;
  CHECK(tait_specific_energy(1.0 + delta, 1.0, 10.0, 7.0, 0.0) == doctest::Approx(50.0 * delta * delta).epsilon(1e-3));
}

// The trapezoid rule is exact for a power linear in time; a restart continues the total it is given.
TEST_CASE("energy budget: the viscous dissipation is the trapezoid sum of minus the power over the steps") {
  const auto power = [](double t) { return -2.0 - 3.0 * t; };  // W = 2 t + 1.5 t^2
  ViscousDissipation w;
  w.start(0.0, power(0.0));
  for (double t : {0.1, 0.25, 0.3, 0.7}) w.step(t, power(t));
  CHECK(w.total() == doctest::Approx(2 * 0.7 + 1.5 * 0.49).epsilon(1e-14));
  CHECK(w.power() == power(0.7));
  ViscousDissipation continued(w.total());  // a restart at t = 0.7
  continued.start(0.7, power(0.7));
  continued.step(1.0, power(1.0));
  CHECK(continued.total() == doctest::Approx(2 * 1.0 + 1.5 * 1.0).epsilon(1e-14));
  // A quadratic power: W's error is -(dt^2 / 12) (P'(T) - P'(0)) for the step dt, exactly.
  ViscousDissipation q;
  q.start(0.0, 0.0);
  const int steps = 10;
  for (int k = 1; k <= steps; ++k) {
    const double t = 0.1 * k;
    q.step(t, -t * t);  // exact W(1) = 1 / 3
  }
  CHECK(q.total() - 1.0 / 3.0 == doctest::Approx(0.01 / 12 * 2.0).epsilon(1e-10));
}
