// Factories of the right-hand-side terms (one file each) and the scene-driven assembly.
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
std::unique_ptr<Term> make_pressure_gradient_colagrossi();
std::unique_ptr<Term> make_pressure_gradient_monaghan();
std::unique_ptr<Term> make_viscosity_morris();
std::unique_ptr<Term> make_viscosity_monaghan();
std::unique_ptr<Term> make_viscosity_direct();     // Basa et al. 2008 model A (eqs. 27-28)
std::unique_ptr<Term> make_viscosity_two_pass();   // Basa et al. 2008 model B (eq. 29)
std::unique_ptr<Term> make_viscosity_violeau();    // Basa et al. 2008 model C (eq. 33)
std::unique_ptr<Term> make_viscosity_cleary(double xi);  // Basa et al. 2008 model D (eq. 34)
std::unique_ptr<Term> make_kernel_correction(const std::string& kind);  // "shepard" | "bonet_lok" (Basa §4)
std::unique_ptr<Term> make_pressure_reduction();   // Basa et al. 2008 eq. 20
std::unique_ptr<Term> make_eos_ideal_gas(double gamma);  // Basa et al. 2008 eq. 12
std::unique_ptr<Term> make_energy_equation();      // Basa et al. 2008 eq. 14
std::unique_ptr<Term> make_body_force(const std::vector<std::string>& expr);

// Names by family for validation and `arksph list`.
std::vector<std::string> viscosity_model_names();
std::vector<std::string> pressure_gradient_names();
std::vector<std::string> kernel_correction_names();  // "none", "shepard", "bonet_lok"

// The terms a scene needs, and nothing else: no body force when it is zero, no viscosity when
// nu = 0, no equation of state or pressure gradient unless the scheme is wcsph, etc.
// sound_speed is the resolved value (see resolve_sound_speed).
std::vector<std::unique_ptr<Term>> terms_from_scene(const Scene& scene, double sound_speed);

// The WCSPH sound speed: the scene's value, or 10 x the reference speed U = max(wall speeds,
// initial speeds, sqrt(|f| L)) with L the largest box length (Szewc §4.1: c >= 10 |u|max).
double resolve_sound_speed(const Scene& scene, double max_initial_speed);

}  // namespace arksph
