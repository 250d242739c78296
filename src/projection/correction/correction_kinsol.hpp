// The Pozorski-Wawrenczuk correction as a nonlinear solve driven by KINSOL with KLU:
// find p* such that the density at the shifted positions r~ - grad p*/rho0 has no fluctuation.
//   F(p)_a = -V_a (s_a(p) - mean s),  s_a(p) = 1 - rho_a(r~ - G p / rho0) / rho0   (Szewc eqs. 57-59)
//   F(p)_0 = -p_0                    (the level of p* is free: pinned)
// At p = 0 this is the right-hand side of the linearised problem (eq. 58) that the fixed-point loop
// solves; its Jacobian is -A with A the pinned, volume-scaled Laplacian of ppe_assembly.hpp, used
// as the (frozen) Newton matrix. Each F evaluation moves the particles and re-sums the density.
#pragma once
#include <vector>

#include "projection/particle_domain.hpp"

namespace arksph {

struct KinsolCorrectionResult {
  long iterations = 0, function_evals = 0;
  int flag = 0;
};

// Shifts the positions in y (time t) of the domain's particles in place (one process: the Jacobian is
// a serial KLU matrix). max_iterations: Newton iterations at most; ftol: KINSOL's scaled residual
// tolerance.
KinsolCorrectionResult correct_density_kinsol(ParticleDomain& domain, double t, double* y, int max_iterations,
                                              double ftol);

}  // namespace arksph
