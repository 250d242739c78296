// Wendland C2 ("quintic") kernel, support 2h. Szewc et al. 2012 eq. 6.
//   f(q) = (1 - q/2)^4 (2q + 1)  (0 <= q < 2)
// 2D constant 7 / (4 pi) (Szewc eq. 6); 1D constant 3/4 (integral of f over the line is 4/3).
#pragma once
#include <numbers>
#include <string_view>

namespace arksph {

// Header-only so that the pair loop can inline eval (kernels/kernel.hpp dispatches once per call).
struct WendlandQuintic {
  static constexpr std::string_view name = "wendland_quintic";  // the scene value of method.kernel
  static constexpr std::string_view summary = "Wendland C2 kernel, support 2h (Szewc et al. 2012 eq. 6)";
  static constexpr double support() { return 2.0; }
  static double sigma(int d) { return d == 1 ? 0.75 : 7.0 / (4.0 * std::numbers::pi); }
  static inline void eval(double q, double& f, double& df) {
    if (q >= 2.0) {
      f = df = 0.0;
      return;
    }
    const double s = 1.0 - 0.5 * q;
    const double s3 = s * s * s;
    f = s3 * s * (2.0 * q + 1.0);
    df = -5.0 * q * s3;  // d/dq [(1-q/2)^4 (2q+1)] = -5 q (1-q/2)^3
  }
  // f and f'(q) / q = -5 (1 - q/2)^3: the gradient factor without a division (hot pair loop).
  static inline void eval_over_q(double q, double& f, double& df_over_q) {
    const double s = q < 2.0 ? 1.0 - 0.5 * q : 0.0;
    const double s3 = s * s * s;
    f = s3 * s * (2.0 * q + 1.0);
    df_over_q = -5.0 * s3;
  }
  // d2f/dq2 = (1-q/2)^2 (10 q - 5) (direct second derivatives, Basa et al. 2008 eq. 28).
  static inline double d2(double q) {
    if (q >= 2.0) return 0.0;
    const double s = 1.0 - 0.5 * q;
    return s * s * (10.0 * q - 5.0);
  }
};

}  // namespace arksph
