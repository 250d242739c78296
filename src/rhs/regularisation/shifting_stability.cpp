#include "rhs/regularisation/shifting_stability.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace arksph {
namespace {

constexpr int kWaveNumbers = 97;  // samples of k per direction over [0, pi / dx] (the rate is smooth in k)

struct Offset {
  double x, y;
  double jxx, jxy, jyy;  // J(r) of the lattice neighbour at r = (x, y)
};

}  // namespace

double shifting_stiffness(const Kernel& kernel, double dx, double anti_clumping) {
  const int dim = kernel.dimension();
  const double w_dx = kernel.W(dx);
  // g(r) = (1 + R (W/W(dx))^4) W'(r), the radial profile of the weighted gradient, and g'(r).
  // J(r) = g'(r) e e^T + g(r) / r (I - e e^T), e = r / |r|.
  std::vector<Offset> offsets;
  const int reach = static_cast<int>(std::ceil(kernel.radius() / dx));
  for (int i = -reach; i <= reach; ++i)
    for (int j = (dim == 2 ? -reach : 0); j <= (dim == 2 ? reach : 0); ++j) {
      const double x = i * dx, y = j * dx, r = std::hypot(x, y);
      if (r == 0 || r >= kernel.radius()) continue;
      const double w = kernel.W(r) / w_dx, w1 = kernel.dWdr(r), w2 = kernel.d2Wdr2(r);
      const double weight = 1 + anti_clumping * w * w * w * w;
      const double g = weight * w1;
      const double g1 = weight * w2 + 4 * anti_clumping * w * w * w * (w1 / w_dx) * w1;
      const double ex = x / r, ey = y / r;
      offsets.push_back({x, y, g1 * ex * ex + g / r * (1 - ex * ex), (g1 - g / r) * ex * ey,
                         g1 * ey * ey + g / r * (1 - ey * ey)});
    }
  const double v0 = std::pow(dx, dim), pi = std::acos(-1.0);
  double fastest = 0;
  for (int p = 0; p < kWaveNumbers; ++p)
    for (int q = 0; q < (dim == 2 ? kWaveNumbers : 1); ++q) {
      const double kx = pi / dx * p / (kWaveNumbers - 1), ky = pi / dx * q / (kWaveNumbers - 1);
      double mxx = 0, mxy = 0, myy = 0;
      for (const Offset& o : offsets) {
        const double c = 1 - std::cos(kx * o.x + ky * o.y);
        mxx += o.jxx * c;
        mxy += o.jxy * c;
        myy += o.jyy * c;
      }
      // The larger eigenvalue of the symmetric 2 x 2 matrix (in 1D, mxx).
      const double top = dim == 2 ? 0.5 * (mxx + myy) + std::hypot(0.5 * (mxx - myy), mxy) : mxx;
      fastest = std::max(fastest, v0 * top);
    }
  return fastest * kernel.h() * kernel.h();
}

}  // namespace arksph
