// Wendland C2 ("quintic") kernel, support 2h. Szewc et al. 2012 eq. 6.
//   f(q) = (1 - q/2)^4 (2q + 1)  (0 <= q < 2)
// 2D constant 7 / (4 pi) (Szewc eq. 6); 1D constant 3/4 (integral of f over the line is 4/3).
#include <numbers>

#include "kernels/kernel_shapes.hpp"

namespace arksph {

struct WendlandQuintic final : KernelShape {
  double support() const override { return 2.0; }
  double sigma(int d) const override { return d == 1 ? 0.75 : 7.0 / (4.0 * std::numbers::pi); }
  void eval(double q, double& f, double& df) const override {
    if (q >= 2.0) {
      f = df = 0.0;
      return;
    }
    const double s = 1.0 - 0.5 * q;
    const double s3 = s * s * s;
    f = s3 * s * (2.0 * q + 1.0);
    df = -5.0 * q * s3;  // d/dq [(1-q/2)^4 (2q+1)] = -5 q (1-q/2)^3
  }
};

std::shared_ptr<const KernelShape> make_wendland_quintic() { return std::make_shared<WendlandQuintic>(); }

}  // namespace arksph
