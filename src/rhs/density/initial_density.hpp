// The WCSPH density at t = 0 from a pressure field: the Tait equation (Cummins & Rudman 1999 eq. 7)
// solved for the density,
//   rho = rho0 (1 + gamma p0 / (c^2 rho0))^(1/gamma),
// with p0 the sum of two optional parts:
// - initial.hydrostatic: under a uniform body force g the pressure at rest,
//   p_h(r) = rho0 (g . r - min_box g . r), i.e. rho0 g (H - y) for g = (0, -g), zero at the highest
//   point of the box (the level of the Tait background pressure). The wall ghosts add the same
//   hydrostatic step to their pressure (rhs/ghost_field.hpp), so the start is a discrete equilibrium
//   up to the kernel's error.
// - initial.pressure: a pressure field p(x, y) given by the user, e.g. the exact pressure of a
//   Taylor-Green vortex, -(rho0 U^2 / 4)(cos 4 pi x + cos 4 pi y).
// A start at rho = rho0 under a pressure-carrying flow sends pressure waves of velocity amplitude
// about p / (rho0 c) through the fluid; starting from the matching density avoids them.
// With a density state (continuity) that density is the initial state; with summation, whose
// density follows the masses, each particle's mass is scaled by rho / rho0.
#pragma once
#include <vector>

#include "core/parameter.hpp"
#include "core/particles.hpp"
#include "core/scene.hpp"

namespace arksph {

const std::vector<Param>& initial_density_params();

// Sets p.init_rho (continuity) or scales p.mass (summation) when initial.hydrostatic or
// initial.pressure is set; sound_speed: the resolved c0. Nothing under the projection schemes.
// Throws InputError where the start is undefined (another equation of state, a force that varies in
// space, several phases, a pressure below the Tait equation's floor -rho0 c^2 / gamma).
void apply_initial_density(const Scene& scene, double sound_speed, ParticleSet& p);

}  // namespace arksph
