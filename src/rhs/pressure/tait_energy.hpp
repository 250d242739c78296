// The specific compressible energy of the Tait equation of state (rhs/pressure/EquationOfState_Tait.cpp),
//   p(rho) = c^2 rho0 / gamma ((rho / rho0)^gamma - 1) + p_b      (C&R eq. 7 with p_b),
// from de/drho = p / rho^2 (the first law without heat flux, Monaghan 1992, Monaghan 2005), e(rho0) = 0. With
// x = rho / rho0 the integral is
//   e(rho) = c^2 / gamma ((x^(gamma - 1) - 1) / (gamma - 1) - (x - 1) / x) + p_b / rho0 (x - 1) / x,
// with ln x for (x^(gamma - 1) - 1) / (gamma - 1) at gamma = 1. Near rho0 the first term is
// c^2 (x - 1)^2 / 2, the acoustic energy; the p_b term is the work against the background pressure.
#pragma once
#include <cmath>

namespace arksph {

inline double tait_specific_energy(double rho, double rho0, double sound_speed, double gamma, double background) {
  const double d = rho / rho0 - 1.0;  // x - 1
  const double log_x = std::log1p(d);
  const double power = gamma == 1.0 ? log_x : std::expm1((gamma - 1.0) * log_x) / (gamma - 1.0);
  const double shrink = d / (1.0 + d);  // (x - 1) / x
  return sound_speed * sound_speed / gamma * (power - shrink) + background / rho0 * shrink;
}

}  // namespace arksph
