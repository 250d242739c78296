#include "boundary/WallVelocity_Linear_Basa2008.hpp"

#include <algorithm>
#include <cmath>

#include "boundary/wall_bins.hpp"

namespace arksph {

namespace {
// Smallest wall distance, in units of dx, that the extrapolation divides by.
constexpr double kMinDistance = 0.5;
}  // namespace

void LinearWallVelocity::apply(const GhostSet& g, std::size_t n_real, const double* x, const double* y, double* u,
                               double* v) const {
  const double* pos[2] = {x, y};
  double* vel[2] = {u, v};
  for_each_no_slip_wall(scene_, dx_, [&](int side, const WallBins& wb, double w_t) {
    const int k = wb.k, t = wb.t;
    // The fluid particle nearest to the wall in each tangential bin.
    nearest_.assign(wb.count(), -1);
    std::vector<double>& best = best_;
    best.assign(wb.count(), 2.0 * dx_);
    for (std::size_t a = 0; a < n_real; ++a) {
      const double d = std::abs(pos[k][a] - wb.plane);
      const auto b = wb.of(pos[t][a]);
      if (d < best[b] && d > 1e-6 * dx_) {
        best[b] = d;
        nearest_[b] = static_cast<long>(a);
      }
    }
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g.wall_side[i] != side) continue;
      const std::size_t gi = n_real + i;
      const long a = nearest_[wb.of(pos[t][gi])];
      if (a < 0) continue;  // no fluid near this stretch of wall: keep the mirror value
      // Extrapolated from at least dx/2, the lattice's first row: from a particle closer to the wall
      // the ratio d_ghost / d_near would amplify its slip without bound (in the driven cavity,
      // particles pushed against a wall gave ghost speeds many times the lid's).
      const double d_near = std::max(std::abs(pos[k][a] - wb.plane), kMinDistance * dx_);
      vel[t][gi] = w_t - g.wall_dist[i] / d_near * (vel[t][a] - w_t);
    }
  });
}

}  // namespace arksph
