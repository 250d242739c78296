// Quadratic extrapolation of the tangential velocity into a no-slip wall, Basa et al. 2008 §6.1.2:
// in each tangential bin (width dx), the parabola through the wall velocity w_t at the wall and the
// velocities of the two fluid particles nearest to the wall (distances d1 < d2) is continued into
// the wall. A ghost at distance d_g behind the wall (s = -d_g on the wall-normal axis) takes
//   u_g,t = w_t L0(s) + u1 L1(s) + u2 L2(s),
//   L0 = (s - d1)(s - d2) / (d1 d2),  L1 = s (s - d2) / (d1 (d1 - d2)),  L2 = s (s - d1) / (d2 (d2 - d1)),
// so that a shear growing linearly with depth continues into the wall (Basa Fig. 3). Where a bin has
// one fluid row only, the linear rule of WallVelocity_Linear_Basa2008 applies; without fluid the
// mirror value stays. The normal component stays mirrored; corner images keep their mirror rule. 2D.
#pragma once
#include <vector>

#include "boundary/wall_velocity_rule.hpp"

namespace arksph {

class QuadraticWallVelocity final : public WallVelocityRule {
 public:
  using WallVelocityRule::WallVelocityRule;
  void apply(const GhostSet& g, std::size_t n_real, const double* x, const double* y, double* u,
             double* v) const override;

 private:
  mutable std::vector<long> first_, second_;  // per tangential bin: nearest and next row (-1: none)
  mutable std::vector<double> d1_, d2_;       // their wall distances (scratch)
};

}  // namespace arksph
