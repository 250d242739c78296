// Factories of the terms that are not selected by name (one file each), and the scene-driven
// assembly of the right-hand side; the named families are in rhs/term_registry.hpp.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "rhs/term.hpp"

namespace arksph {

std::unique_ptr<Term> make_density_summation();
std::unique_ptr<Term> make_eos_tait(double sound_speed, double gamma, double background);
std::unique_ptr<Term> make_continuity();
std::unique_ptr<Term> make_pressure_reduction();   // Basa et al. 2008 eq. 20
std::unique_ptr<Term> make_eos_ideal_gas(double gamma);  // Basa et al. 2008 eq. 12
std::unique_ptr<Term> make_energy_equation();      // Basa et al. 2008 eq. 14
std::unique_ptr<Term> make_body_force(const std::vector<std::string>& expr);
// delta-SPH (method.density_diffusion = "delta_sph") with the resolved sound speed.
std::unique_ptr<Term> make_density_diffusion(const Scene& scene, double sound_speed);

// The terms a scene needs, and nothing else: no body force when it is zero, no viscosity when
// nu = 0, no equation of state or pressure gradient unless the scheme is wcsph, etc.
// sound_speed is the resolved value (see resolve_sound_speed).
std::vector<std::unique_ptr<Term>> terms_from_scene(const Scene& scene, double sound_speed);

// The WCSPH sound speed: the scene's value, or 10 x the reference speed U = max(wall speeds,
// initial speeds, sqrt(|f| L)) with L the largest box length (Szewc §4.1: c >= 10 |u|max).
double resolve_sound_speed(const Scene& scene, double max_initial_speed);

}  // namespace arksph
