// The errors against an exact velocity field (diagnostics/exact_velocity.hpp) on hand-made particle
// fields over a lattice of the periodic unit square, against values known in closed form.
#include <doctest/doctest.h>

#include <cmath>

#include "diagnostics/exact_velocity.hpp"

using namespace arksph;

namespace {

constexpr double kExactPi = 3.14159265358979323846;
// Sums of a few hundred terms of size 1: round-off well below 1e-12 of the values checked.
constexpr double kExactRoundOff = 1e-12;

// The Taylor-Green mode at t = 0 on the cell centres of an n x n lattice, each particle scaled by
// scale(x) plus a uniform drift (cx, 0); masses m(x), densities 1.
template <class Scale, class Mass>
FluidFields vortex(int n, Scale scale, double cx, Mass mass) {
  FluidFields f;
  f.dim = 2;
  f.t = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5) / n, y = (j + 0.5) / n;
      f.x.push_back(x);
      f.y.push_back(y);
      f.u.push_back(-std::cos(2 * kExactPi * x) * std::sin(2 * kExactPi * y) * scale(x) + cx);
      f.v.push_back(std::sin(2 * kExactPi * x) * std::cos(2 * kExactPi * y) * scale(x));
      f.m.push_back(mass(x));
      f.rho.push_back(1.0);
    }
  f.n_real = f.n_all = f.x.size();
  return f;
}

const ExactVelocity kTaylorGreen({"-cos(2*pi*x)*sin(2*pi*y)", "sin(2*pi*x)*cos(2*pi*y)"});

}  // namespace

TEST_CASE("exact velocity: the amplitude error is the fitted multiple of the mode, blind to what is orthogonal to it") {
  const auto one = [](double) { return 1.0; };
  SUBCASE("0.9 times the mode plus a uniform drift: amplitude -0.1, the peak error sees the drift") {
    // The drift (0.05, 0) is orthogonal to the mode on the symmetric lattice (sum of u_exact = 0).
    const ExactVelocityErrors e = kTaylorGreen.errors(vortex(20, [](double) { return 0.9; }, 0.05, one));
    CHECK(e.amplitude_error == doctest::Approx(-0.1).epsilon(kExactRoundOff));
    // The fastest particle moves faster than 0.9 of the exact peak: the drift adds to it.
    CHECK(e.peak_speed_error > -0.1 + 0.01);
  }
  SUBCASE("the fit weighs particles by their volume m / rho") {
    // 0.8 of the mode on x < 1/2 with volume 2, the mode itself on x > 1/2 with volume 1; |u_exact|^2
    // has the same sum on both halves, so a = (2 * 0.8 + 1 * 1) / (2 + 1) = 2.6 / 3.
    const auto scale = [](double x) { return x < 0.5 ? 0.8 : 1.0; };
    const auto mass = [](double x) { return x < 0.5 ? 2.0 : 1.0; };
    const ExactVelocityErrors e = kTaylorGreen.errors(vortex(20, scale, 0.0, mass));
    CHECK(e.amplitude_error == doctest::Approx(2.6 / 3 - 1).epsilon(kExactRoundOff));
    // Equal volumes would give (0.8 + 1) / 2 = 0.9: the weighting matters.
    CHECK(kTaylorGreen.errors(vortex(20, scale, 0.0, one)).amplitude_error == doctest::Approx(-0.1).epsilon(kExactRoundOff));
  }
  SUBCASE("the exact field itself: every error vanishes") {
    const ExactVelocityErrors e = kTaylorGreen.errors(vortex(16, one, 0.0, one));
    CHECK(std::abs(e.amplitude_error) < kExactRoundOff);
    CHECK(std::abs(e.peak_speed_error) < kExactRoundOff);
    CHECK(e.l1_relative < kExactRoundOff);
  }
}
