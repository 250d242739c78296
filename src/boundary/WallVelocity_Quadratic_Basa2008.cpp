#include "boundary/WallVelocity_Quadratic_Basa2008.hpp"

#include <algorithm>
#include <cmath>

#include "boundary/wall_bins.hpp"

namespace arksph {

void QuadraticWallVelocity::apply(const GhostSet& g, std::size_t n_real, const double* x, const double* y, double* u,
                                  double* v) const {
  const double* pos[2] = {x, y};
  double* vel[2] = {u, v};
  for_each_no_slip_wall(scene_, dx_, [&](int side, const WallBins& wb, double w_t) {
    const int k = wb.k, t = wb.t;
    const std::size_t nb = wb.count();
    // Nearest fluid particle in each bin, then the nearest one at least dx/2 further from the wall.
    first_.assign(nb, -1);
    second_.assign(nb, -1);
    std::vector<double>& d1 = d1_;  // member scratch: no allocation in f
    std::vector<double>& d2 = d2_;
    d1.assign(nb, 3.0 * dx_);
    d2.assign(nb, 4.0 * dx_);
    for (std::size_t a = 0; a < n_real; ++a) {
      const double d = std::abs(pos[k][a] - wb.plane);
      const auto b = wb.of(pos[t][a]);
      if (d < d1[b] && d > 1e-6 * dx_) d1[b] = d, first_[b] = static_cast<long>(a);
    }
    for (std::size_t a = 0; a < n_real; ++a) {
      const double d = std::abs(pos[k][a] - wb.plane);
      const auto b = wb.of(pos[t][a]);
      if (first_[b] >= 0 && d > d1[b] + 0.5 * dx_ && d < d2[b]) d2[b] = d, second_[b] = static_cast<long>(a);
    }
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g.wall_side[i] != side) continue;
      const std::size_t gi = n_real + i;
      const auto b = wb.of(pos[t][gi]);
      const long a1 = first_[b], a2 = second_[b];
      if (a1 < 0) continue;  // no fluid near this stretch of wall: keep the mirror value
      const double s_g = -g.wall_dist[i], e1 = d1[b];
      const double u1 = vel[t][a1];
      if (a2 < 0) {  // one row only: linear extrapolation
        vel[t][gi] = w_t + s_g / e1 * (u1 - w_t);
        continue;
      }
      const double e2 = d2[b], u2 = vel[t][a2];
      const double l0 = (s_g - e1) * (s_g - e2) / (e1 * e2);
      const double l1 = s_g * (s_g - e2) / (e1 * (e1 - e2));
      const double l2 = s_g * (s_g - e1) / (e2 * (e2 - e1));
      vel[t][gi] = w_t * l0 + u1 * l1 + u2 * l2;
    }
  });
}

}  // namespace arksph
