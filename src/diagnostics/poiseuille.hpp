// Start-up Poiseuille flow, Basa, Quinlan & Lastiwka 2008 §6.1.
#pragma once
#include "core/scene.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

// Series solution (Basa eq. 36; the extracted text garbles it, this is the standard form):
//   U(y,t)/U0 = 1 - (y/d)^2 - 32/pi^3 sum_n (-1)^n/(2n+1)^3 cos((2n+1) pi y / (2d))
//               exp(-(2n+1)^2 pi^2 nu t / (4 d^2)),
// y from the centreline, channel width 2d, U0 = f d^2 / (2 nu) (Basa eq. 37 with f per unit mass).
double poiseuille_velocity(double y, double t, double d, double nu, double force);

// Basa eq. 39: t* = t pi^2 nu / (4 d^2).
double poiseuille_tstar(double t, double d, double nu);

// Basa eq. 38: eps = sqrt(1/N sum_a ((u_a - U(y_a,t)) / U(y_a,t))^2) over fluid particles,
// walls at y_lo and y_hi. Returns NaN at t = 0 where U vanishes.
double poiseuille_epsilon(const FluidFields& f, double y_lo, double y_hi, double nu, double force);

// The driving force per unit mass of the scene's channel: fluid.body_force[0] (a constant).
double poiseuille_force(const Scene& s);

}  // namespace arksph
