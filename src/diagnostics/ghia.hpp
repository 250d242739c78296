// Centreline errors against Ghia, Ghia & Shin 1982 (Tables I and II) for the lid-driven cavity.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "kernels/kernel.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

struct GhiaErrors {
  double u_linf = 0, u_rms = 0, v_linf = 0, v_rms = 0;
  std::vector<double> u_coord, u_ref, u_sph;  // u along x = 0.5 at Ghia's y (interior points)
  std::vector<double> v_coord, v_ref, v_sph;  // v along y = 0.5 at Ghia's x (interior points)
};

// Velocity at a point by a Shepard-normalised kernel interpolation over fluid particles only:
//   u(r) = sum_b V_b u_b W(r - r_b) / sum_b V_b W(r - r_b),  V_b = m_b / rho_b,
// with the given interpolation kernel (independent of the simulation's kernel).
void shepard_velocity(const FluidFields& f, const Kernel& w, double px, double py, double& u, double& v);
// The sums of that interpolation over the real particles [0, n) of f: {sum V u W, sum V v W, sum V W}
// (they add up over disjoint sets of particles; u = sums[0] / sums[2] where sums[2] > 0, else 0).
std::array<double, 3> shepard_sums(const FluidFields& f, const Kernel& w, double px, double py, std::size_t n);
double shepard_ratio(double num, double den);

// The interpolation used for Ghia comparisons: Wendland C2 with h = 1.3 dx over fluid particles, the
// interpolation that published peer-code cavity figures were measured with, so that they compare directly.
Kernel ghia_interpolation_kernel(double dx);

// Compares with Ghia's table at Re (100 or 1000) for a cavity [x0, x0 + L] x [y0, y0 + L] with lid
// speed U (velocities scaled by U, coordinates by L). The wall rows of the table are left out.
GhiaErrors ghia_errors(const FluidFields& f, int re, double x0, double y0, double length, double lid_speed,
                       double dx);

// The same in two parts, for sums gathered elsewhere (a decomposed run): the sample points of a
// cavity [x0, x0 + L] x [y0, y0 + L] (Table I's on x = 0.5, then Table II's on y = 0.5), and the
// errors from the velocities interpolated there (u at Table I's points, v at Table II's).
std::vector<std::array<double, 2>> ghia_points(double x0, double y0, double length);
std::size_t ghia_u_point_count();
GhiaErrors ghia_errors_at(int re, double lid_speed, const std::vector<double>& u, const std::vector<double>& v);

}  // namespace arksph
