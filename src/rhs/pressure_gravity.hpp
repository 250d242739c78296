// Gravity in the pressure: the modified pressure of an incompressible fluid of one density.
//
// Under a body force g uniform in space, an incompressible fluid of one density rho0 moves exactly
// as without it once the pressure is written P = p - rho0 g . r: the momentum equation
// du/dt = -grad(p)/rho0 + g + ... becomes du/dt = -grad(P)/rho0 + ..., and at a resting wall
// dp/dn = rho0 g . n becomes dP/dn = 0. The projection schemes solve for P, so that a
// closed tank at rest has P = const: its discrete rest state is exact, whatever the particles'
// disorder. Solving for p instead, as the pressure equation with the body force's wall flux does
// (projection/body_force_split.hpp), leaves a residual acceleration g - G(p) / rho0 at rest, the
// SPH gradient's error for the large linear hydrostatic p on disordered particles: with C&R's
// approximate projection (L != D G) part of it is never removed, the particles drift (the mean
// density of a tank at rest rose 10 % by t = 5 at the viscous step limit) and the constrained
// projection, which integrates it as an acceleration, blows up (docs/methods/isph.md).
//
// Chosen by method.body_force_pressure = "modified" (its automatic value wherever it applies): the
// projection schemes (isph, isph-gpps) with one density (no [[phase]] of another density), no free
// surface (fluid.region), and a
// constant body force, its components along axes
// bounded by walls; along a periodic axis g drives a flow (a channel) and stays in the momentum
// equation. The reported pressure is p = P + rho0 (g . r - min g . r) over the particles: the
// hydrostatic part is zero at the highest particle. Two phases keep g in the momentum equation
// (the split of body_force_split.hpp): their buoyancy is the flow.
#pragma once
#include <string>
#include <vector>

#include "core/option.hpp"
#include "core/scene.hpp"

namespace arksph {

// method.body_force_pressure: the body force in the pressure (modified) or in the momentum equation
// (split); the key is declared with the projection's keys (projection/projection.cpp).
const Option<BodyForcePressure>& body_force_pressures();

struct PressureGravity {
  bool active = false;
  double g[2] = {0.0, 0.0};  // the components the pressure takes
  double rho0 = 0;
  // g . r of each of n points (y null in 1D): the hydrostatic pressure over rho0, up to a constant.
  std::vector<double> head(std::size_t n, const double* x, const double* y) const;
};

// One density and a constant body force with a component along a walled axis, under a projection
// scheme: what method.body_force_pressure = "modified" needs.
bool modified_pressure_applies(const Scene& scene);
// What of the scene's body force its pressure takes (active: something): nothing unless
// method.body_force_pressure = "modified" (InputError, one line, where that does not apply).
PressureGravity pressure_gravity(const Scene& scene);
// The body force the momentum equation keeps: fluid.body_force with the components the pressure
// takes replaced by "0".
std::vector<std::string> momentum_body_force(const Scene& scene);

}  // namespace arksph
