// Cubic B-spline, support 2h.
// Cummins & Rudman 1999 eq. 5 (1D constant 2/3); Szewc et al. 2012 eq. 5 (2D constant 10/(7 pi)).
//   f(q) = 1 - 3/2 q^2 + 3/4 q^3  (0 <= q < 1),  1/4 (2 - q)^3  (1 <= q < 2)
#pragma once
#include <numbers>
#include <string_view>

namespace arksph {

// Header-only so that the pair loop can inline eval (kernels/kernel.hpp dispatches once per call).
struct CubicSpline {
  static constexpr std::string_view name = "cubic_spline";  // the scene value of method.kernel
  static constexpr std::string_view summary = "cubic B-spline, support 2h (Cummins & Rudman 1999 eq. 5, Szewc et al. 2012 eq. 5)";
  static constexpr double support() { return 2.0; }
  static double sigma(int d) { return d == 1 ? 2.0 / 3.0 : 10.0 / (7.0 * std::numbers::pi); }
  static inline void eval(double q, double& f, double& df) {
    if (q < 1.0) {
      f = 1.0 - 1.5 * q * q + 0.75 * q * q * q;
      df = -3.0 * q + 2.25 * q * q;
    } else if (q < 2.0) {
      const double s = 2.0 - q;
      f = 0.25 * s * s * s;
      df = -0.75 * s * s;
    } else {
      f = df = 0.0;
    }
  }
  // d2f/dq2 (direct second derivatives, Basa et al. 2008 eq. 28).
  static inline double d2(double q) { return q < 1.0 ? -3.0 + 4.5 * q : (q < 2.0 ? 1.5 * (2.0 - q) : 0.0); }
};

}  // namespace arksph
