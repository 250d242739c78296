// Particles that cross a wall are put back by reflection, between steps.
//
// With mirror ghosts a wall is a symmetry plane: a particle at distance d from it meets its own
// image at distance 2d, and with kernels whose gradient vanishes at r = 0 (all of ours) the pair
// repulsion vanishes as d -> 0. Nothing then stops a particle that is pushed hard enough (e.g. by the
// lid into a cavity corner) from passing through its image; once outside it is lost. Reflecting it
// (position 2 x_w - x, normal velocity 2 w_n - u_n) keeps it in the fluid. This changes the state y
// outside ARKODE, so the run loop re-initialises the integrator afterwards (a sync point) and counts
// the reflections in summary.json ("wall_reflections").
#pragma once
#include "core/particles.hpp"
#include "core/scene.hpp"

namespace arksph {

class WallReflection {
 public:
  WallReflection(const Scene& scene, const StateLayout& layout) : scene_(scene), layout_(layout) {}
  // Reflects every particle found beyond a wall; returns how many were reflected.
  long apply(double* y) const;

 private:
  const Scene& scene_;
  StateLayout layout_;
};

}  // namespace arksph
