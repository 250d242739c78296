// What C&R's projection (projection.hpp) does differently at a free surface (fluid.region):
//
//   - rows of given pressure at the surface particles, found by the divergence of position (Shao &
//     Lo 2003; Lind et al. 2012 §2.3, threshold 0.75 d), p = 0 half a spacing beyond them:
//     surface_rows;
//   - the velocity correction by a gradient exact for a linear P at a cut support: the
//     renormalised difference gradient at the surface rows, the neighbour-based one below them
//     (velocity_correction.hpp: subtract_renormalised_gradient);
//   - the Laplacian made exact for a linear P at a cut support: linear_laplacian_defect, lagged by
//     one projection and moved to the source, so that the matrix stays C&R's eq. 19 (symmetric
//     positive definite: every Poisson solver, hypre over ranks included, takes it unchanged).
//
// docs/methods/free-surface.md measures each of the three.
#pragma once
#include <cstddef>
#include <vector>

#include "projection/particle_domain.hpp"
#include "projection/ppe_assembly.hpp"
#include "projection/velocity_correction.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

// The rows of given pressure at the surface particles (div r below `threshold`). The surface itself
// lies `depth` beyond them (half a spacing: where the lattice's next row would sit), where p = 0;
// each surface particle takes p = depth dp/dn, the inward derivative of the last projection's P
// (`last`: its renormalised gradients, renormalised_gradients in velocity_correction.hpp, taken
// along the inward normal sum_b V_b grad_a W_ab / |...|), not below 0. With `last` empty, or where
// the gradient is near-singular, p = 0 at the particle. A column at rest then reads p = rho g (H - y) to the
// surface's height H, not to its top particles' (rho g dx / 2 less).
DirichletRows surface_rows(const FluidFields& f, std::size_t n, double threshold, double depth,
                           const std::vector<RenormalisedGradient>& last);

// C&R eq. 19 applied to a linear P = P_0 + r . G reads, with p_a - p_b = r_ab . G,
//   L(P)_a = c_a . G,   c_a = sum_b V_b 4/(rho_a + rho_b) F_ab r_ab^2/(r_ab^2 + eta^2) r_ab
// (grad_a W_ab = F_ab r_ab), which vanishes on a full symmetric support and not where a free surface
// cuts it: below the surface the solved P then bends away from the hydrostatic line and a column at
// rest moves. Returns c_a . grad P_a for each of the first n particles, grad P_a the renormalised
// difference gradient of P (`grad`: renormalised_gradients in velocity_correction.hpp; 0 where it
// is near-singular).
// L(P)_a - c_a . grad P_a is then exact for a linear P at any support.
std::vector<double> linear_laplacian_defect(const FluidFields& f, const std::vector<RenormalisedGradient>& grad,
                                            std::size_t n);

}  // namespace arksph
