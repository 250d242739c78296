// WCSPH started in hydrostatic balance (initial.hydrostatic): under a uniform body force g the
// pressure at rest is p_h(r) = rho0 (g . r - min_box g . r), i.e. rho0 g (H - y) for g = (0, -g)
// (zero at the highest point of the box, the level of the Tait background pressure), and the
// density at t = 0 is the Tait equation (Cummins & Rudman 1999 eq. 7) solved for it:
//   rho = rho0 (1 + gamma p_h / (c^2 rho0))^(1/gamma).
// With a density state (continuity) that density is the initial state; with summation, whose
// density follows the masses, each particle's mass is scaled by rho / rho0. The wall ghosts add the
// same hydrostatic step to their pressure (rhs/ghost_field.hpp), so the start is a discrete
// equilibrium up to the kernel's error, without the pressure waves of a start at rho = rho0.
#pragma once
#include <vector>

#include "core/parameter.hpp"
#include "core/particles.hpp"
#include "core/scene.hpp"

namespace arksph {

const std::vector<Param>& hydrostatic_start_params();

// Sets p.init_rho (continuity) or scales p.mass (summation) when scene.initial_hydrostatic is set;
// sound_speed: the resolved c0. Nothing under the projection schemes. Throws InputError where the
// start is undefined (another equation of state, a force that varies in space, several phases).
void apply_hydrostatic_start(const Scene& scene, double sound_speed, ParticleSet& p);

}  // namespace arksph
