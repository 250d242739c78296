// The reference speed U of a scene: the largest of the wall speeds, the initial speeds and
// sqrt(|f| L) (f the body force at the box centre, L the largest box length). It scales the
// regularisation velocities (rhs/Shifting_Lind2012.cpp, rhs/TransportVelocity_Adami2013.cpp) and,
// times ten, the default WCSPH sound speed.
#pragma once
#include "core/scene.hpp"

namespace arksph {

// With the initial speeds sampled at the lattice points of the box (spacing fluid.spacing).
double reference_speed(const Scene& scene);
// With the given largest initial speed instead of the sampled one.
double reference_speed(const Scene& scene, double max_initial_speed);

}  // namespace arksph
