// Quartic B-spline, support 2.5h. Cummins & Rudman 1999 eq. 6.
//   f(q) = (2.5-q)^4 - 5 (1.5-q)^4 + 10 (0.5-q)^4   (0 <= q < 0.5)
//          (2.5-q)^4 - 5 (1.5-q)^4                  (0.5 <= q < 1.5)
//          (2.5-q)^4                                (1.5 <= q < 2.5)
// The paper prints the 2D constant as 0.0255; the exact value is 96 / (1199 pi) = 0.025486...
// The 1D constant is 1/24 (the integral of the bracket over the real line is 24).
#pragma once
#include <numbers>
#include <string_view>

namespace arksph {

// Header-only so that the pair loop can inline eval (kernels/kernel.hpp dispatches once per call).
struct QuarticSpline {
  static constexpr std::string_view name = "quartic_spline";  // the scene value of method.kernel
  static constexpr std::string_view summary = "quartic B-spline, support 2.5h (Cummins & Rudman 1999 eq. 6)";
  static constexpr double support() { return 2.5; }
  static double sigma(int d) { return d == 1 ? 1.0 / 24.0 : 96.0 / (1199.0 * std::numbers::pi); }
  static inline void eval(double q, double& f, double& df) {
    f = df = 0.0;
    if (q >= 2.5) return;
    const double a = 2.5 - q;
    f += a * a * a * a;
    df -= 4.0 * a * a * a;
    if (q < 1.5) {
      const double b = 1.5 - q;
      f -= 5.0 * b * b * b * b;
      df += 20.0 * b * b * b;
    }
    if (q < 0.5) {
      const double c = 0.5 - q;
      f += 10.0 * c * c * c * c;
      df -= 40.0 * c * c * c;
    }
  }
  // d2f/dq2 (direct second derivatives, Basa et al. 2008 eq. 28).
  static inline double d2(double q) {
    if (q >= 2.5) return 0.0;
    double s = 12.0 * (2.5 - q) * (2.5 - q);
    if (q < 1.5) s -= 60.0 * (1.5 - q) * (1.5 - q);
    if (q < 0.5) s += 120.0 * (0.5 - q) * (0.5 - q);
    return s;
  }
};

}  // namespace arksph
