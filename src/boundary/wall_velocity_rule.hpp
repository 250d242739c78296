// A rule for the tangential velocity of the single-wall ghosts of no-slip walls, applied after the
// mirror construction of boundary/ghosts.hpp ("mirror" itself needs no rule). The rules are
// registered by name in wall_velocity_rules.cpp (boundary.wall_velocity).
#pragma once
#include <cstddef>

#include "boundary/ghosts.hpp"
#include "core/scene.hpp"

namespace arksph {

class WallVelocityRule {
 public:
  WallVelocityRule(const Scene& scene, double dx) : scene_(scene), dx_(dx) {}
  virtual ~WallVelocityRule() = default;
  // u, v: velocities of all points (real then ghosts); overwrites the tangential component of the
  // single-wall mirror ghosts of no-slip walls.
  virtual void apply(const GhostSet& g, std::size_t n_real, const double* x, const double* y, double* u,
                     double* v) const = 0;

 protected:
  const Scene& scene_;
  double dx_;
};

}  // namespace arksph
