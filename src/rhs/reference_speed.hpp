// The speed scales of a scene. The reference speed: the largest of the wall speeds, the initial
// speeds and sqrt(|f| L) (f the body force at the box centre, L the largest box length); times ten,
// the default WCSPH sound speed. The flow speed (core/flow_speed.hpp): the largest wall or initial
// speed only, the scale of the regularisation velocities (rhs/regularisation/Shifting_Lind2012.cpp,
// rhs/regularisation/TransportVelocity_Adami2013.cpp): a fluid that starts at rest between walls at
// rest (a tank under gravity) is not shifted.
#pragma once
#include "core/flow_speed.hpp"
#include "core/scene.hpp"

namespace arksph {

// With the initial speeds sampled at the lattice points of the box (spacing fluid.spacing).
double reference_speed(const Scene& scene);
// With the given largest initial speed instead of the sampled one.
double reference_speed(const Scene& scene, double max_initial_speed);

}  // namespace arksph
