// Quintic B-spline of Morris et al., support 3h. Szewc et al. 2012 eq. 7.
//   f(q) = (3-q)^5 - 6 (2-q)^5 + 15 (1-q)^5  (0 <= q < 1)
//          (3-q)^5 - 6 (2-q)^5               (1 <= q < 2)
//          (3-q)^5                           (2 <= q < 3)
// 2D constant 7 / (478 pi) (Szewc eq. 7); 1D constant 1/120.
#pragma once
#include <numbers>
#include <string_view>

namespace arksph {

// Header-only so that the pair loop can inline eval (kernels/kernel.hpp dispatches once per call).
struct QuinticSpline {
  static constexpr std::string_view name = "quintic_spline";  // the scene value of method.kernel
  static constexpr std::string_view summary = "quintic B-spline of Morris et al., support 3h (Szewc et al. 2012 eq. 7)";
  static constexpr double support() { return 3.0; }
  static double sigma(int d) { return d == 1 ? 1.0 / 120.0 : 7.0 / (478.0 * std::numbers::pi); }
  static inline void eval(double q, double& f, double& df) {
    f = df = 0.0;
    if (q >= 3.0) return;
    auto add = [&](double c, double s) {  // c * s^5 and its q-derivative -5 c s^4
      const double s2 = s * s, s4 = s2 * s2;
      f += c * s4 * s;
      df -= 5.0 * c * s4;
    };
    add(1.0, 3.0 - q);
    if (q < 2.0) add(-6.0, 2.0 - q);
    if (q < 1.0) add(15.0, 1.0 - q);
  }
  // d2f/dq2 = sum 20 c s^3 (direct second derivatives, Basa et al. 2008 eq. 28).
  static inline double d2(double q) {
    if (q >= 3.0) return 0.0;
    auto term = [](double c, double s) { return 20.0 * c * s * s * s; };
    double v = term(1.0, 3.0 - q);
    if (q < 2.0) v += term(-6.0, 2.0 - q);
    if (q < 1.0) v += term(15.0, 1.0 - q);
    return v;
  }
};

}  // namespace arksph
