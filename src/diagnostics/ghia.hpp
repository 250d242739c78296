// Centreline errors against Ghia, Ghia & Shin 1982 (Tables I and II) for the lid-driven cavity.
#pragma once
#include <vector>

#include "rhs/fluid_fields.hpp"

namespace arksph {

struct GhiaErrors {
  double u_linf = 0, u_rms = 0, v_linf = 0, v_rms = 0;
  std::vector<double> u_coord, u_ref, u_sph;  // u along x = 0.5 at Ghia's y (interior points)
  std::vector<double> v_coord, v_ref, v_sph;  // v along y = 0.5 at Ghia's x (interior points)
};

// Velocity at a point by a Shepard-normalised kernel interpolation over fluid particles only:
//   u(r) = sum_b V_b u_b W(r - r_b) / sum_b V_b W(r - r_b),  V_b = m_b / rho_b.
// Fluid only, because the no-slip ghosts carry 2w - u, which would pull the estimate towards w
// twice near the wall; the Shepard denominator corrects the truncated support there instead.
void shepard_velocity(const FluidFields& f, double px, double py, double& u, double& v);

// Compares with Ghia's table at Re (100 or 1000) for a cavity [x0, x0 + L] x [y0, y0 + L] with lid
// speed U (velocities scaled by U, coordinates by L). The wall rows of the table are left out.
GhiaErrors ghia_errors(const FluidFields& f, int re, double x0, double y0, double length, double lid_speed);

}  // namespace arksph
