// The flow speed of a scene: the largest wall or initial speed, the scale of the regularisation
// velocities (rhs/regularisation/) and of the automatic rules that ask whether a walled box holds a
// flow (boundary/walled_flow.hpp). The reference speed (rhs/reference_speed.hpp) adds the body force.
#pragma once
#include "core/scene.hpp"

namespace arksph {

// The largest wall speed, or u_ref if that is larger.
double largest_wall_speed(const Scene& scene, double u_ref);
// The largest initial speed, sampled at the lattice points of the fluid (spacing fluid.spacing).
double largest_initial_speed(const Scene& scene);
// The largest wall or initial speed (initial speeds sampled at the lattice points).
double flow_speed(const Scene& scene);

}  // namespace arksph
