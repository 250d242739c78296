// Linear extrapolation of the tangential velocity into a no-slip wall, Basa et al. 2008 §6.1.2:
// instead of mirroring its own source (2w - u), a ghost at distance d_g behind the wall takes the
// wall shear measured by the fluid particle nearest to the wall at the same tangential position,
//   u_g,t = w_t - (d_g / d_near) (u_near,t - w_t),
// so the shear field continues into the wall at constant rate (Basa Fig. 3). The normal component
// stays mirrored. Corner images keep their mirror rule. 2D only. d_near is held at dx/2 or more
// (the first lattice row), so a particle pressed against the wall does not blow the ghosts up.
#pragma once
#include <vector>

#include "boundary/wall_velocity_rule.hpp"

namespace arksph {

class LinearWallVelocity final : public WallVelocityRule {
 public:
  using WallVelocityRule::WallVelocityRule;
  void apply(const GhostSet& g, std::size_t n_real, const double* x, const double* y, double* u,
             double* v) const override;

 private:
  mutable std::vector<double> best_;  // per tangential bin: its wall distance (scratch, kept to avoid allocation)
  mutable std::vector<long> nearest_;  // per tangential bin: nearest real particle (-1: none)
};

}  // namespace arksph
