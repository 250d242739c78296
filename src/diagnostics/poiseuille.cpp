#include "diagnostics/poiseuille.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/expression.hpp"

namespace arksph {

double poiseuille_velocity(double y, double t, double d, double nu, double force) {
  const double pi = std::numbers::pi;
  const double u0 = force * d * d / (2.0 * nu);
  double series = 0;
  for (int n = 0; n < 200; ++n) {
    const double k = 2.0 * n + 1.0;
    const double decay = std::exp(-k * k * pi * pi * nu * t / (4.0 * d * d));
    if (decay < 1e-300) break;
    series += (n % 2 ? -1.0 : 1.0) / (k * k * k) * std::cos(k * pi * y / (2.0 * d)) * decay;
  }
  return u0 * (1.0 - (y / d) * (y / d) - 32.0 / (pi * pi * pi) * series);
}

double poiseuille_tstar(double t, double d, double nu) {
  return t * std::numbers::pi * std::numbers::pi * nu / (4.0 * d * d);
}

double poiseuille_epsilon(const FluidFields& f, double y_lo, double y_hi, double nu, double force) {
  if (f.t <= 0) return std::numeric_limits<double>::quiet_NaN();
  const double d = 0.5 * (y_hi - y_lo), yc = 0.5 * (y_hi + y_lo);
  double sum = 0;
  for (std::size_t a = 0; a < f.n_real; ++a) {
    const double exact = poiseuille_velocity(f.y[a] - yc, f.t, d, nu, force);
    const double rel = (f.u[a] - exact) / exact;
    sum += rel * rel;
  }
  return std::sqrt(sum / static_cast<double>(f.n_real));
}

double poiseuille_force(const Scene& s) { return Expression(s.body_force.at(0), {"x", "y", "t"}).eval(0, 0, 0); }

}  // namespace arksph
