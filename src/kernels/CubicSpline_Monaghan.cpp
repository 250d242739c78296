// Cubic B-spline, support 2h.
// Cummins & Rudman 1999 eq. 5 (1D constant 2/3); Szewc et al. 2012 eq. 5 (2D constant 10/(7 pi)).
//   f(q) = 1 - 3/2 q^2 + 3/4 q^3  (0 <= q < 1),  1/4 (2 - q)^3  (1 <= q < 2)
#include <cmath>
#include <numbers>

#include "kernels/kernel_shapes.hpp"

namespace arksph {

struct CubicSpline final : KernelShape {
  double support() const override { return 2.0; }
  double sigma(int d) const override { return d == 1 ? 2.0 / 3.0 : 10.0 / (7.0 * std::numbers::pi); }
  void eval(double q, double& f, double& df) const override {
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
};

std::shared_ptr<const KernelShape> make_cubic_spline() { return std::make_shared<CubicSpline>(); }

}  // namespace arksph
