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
// Each particle's mass is scaled by rho / rho0, so that its volume m / rho stays the lattice cell
// it was placed in; with a density state (continuity) rho is also the initial state (with
// summation the density follows the masses). A continuity density raised at the unscaled mass
// rho0 dx^d would make the volumes V_b = m_b / rho_b of the pressure gradient's sums smaller than
// the cells by rho0 / rho_b. Under gravity the symmetric gradient (1 / rho_a) sum_b V_b (p_a + p_b)
// grad W_ab then reads the hydrostatic profile, on the lattice, as (1 - 2 p / (rho c^2)) grad p / rho^2,
// about (1 - 3 p / (rho0 c^2)) of grad p / rho: the fluid at rest settles to dp/dy about
// (1 + 4 p / (rho0 c^2)) rho0 g instead of the weakly compressible rho g, i.e. (1 + p / (rho0 c^2)) rho0 g
// (measured in docs/methods/free-surface.md).
#pragma once
#include <vector>

#include "core/parameter.hpp"
#include "core/particles.hpp"
#include "core/scene.hpp"

namespace arksph {

const std::vector<Param>& initial_density_params();

// Scales p.mass and, with a density state (continuity), sets p.init_rho when initial.hydrostatic or
// initial.pressure is set; sound_speed: the resolved c0. Nothing under the projection schemes.
// Throws InputError where the start is undefined (another equation of state, a force that varies in
// space, several phases, a pressure below the Tait equation's floor -rho0 c^2 / gamma).
void apply_initial_density(const Scene& scene, double sound_speed, ParticleSet& p);

}  // namespace arksph
