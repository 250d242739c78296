// Assembles the right-hand side from the scene: parts by name from the registries, and the rules
// that leave out what a scene does not need.
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/errors.hpp"
#include "core/expression.hpp"
#include "core/scheme.hpp"
#include "rhs/pressure_gravity.hpp"
#include "rhs/reference_speed.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {
namespace {
// The term of a registered part, carrying the part's traits.
std::unique_ptr<Term> build(const Part<TermFactory>& part, const Scene& scene) {
  std::unique_ptr<Term> term = part.make(scene);
  term->set_traits(part.traits);
  return term;
}

bool is_zero_force(const std::vector<std::string>& expr) {
  for (const auto& e : expr) {
    Expression ex(e, {"x", "y", "t"});
    if (!ex.is_constant() || ex.eval(0, 0, 0) != 0.0) return false;
  }
  return true;
}
}  // namespace

double resolve_sound_speed(const Scene& scene, double max_initial_speed) {
  if (scene.sound_speed > 0) return scene.sound_speed;
  const double u_ref = reference_speed(scene, max_initial_speed);
  return u_ref > 0 ? 10.0 * u_ref : 1.0;
}

std::vector<std::unique_ptr<Term>> terms_from_scene(const Scene& scene, double sound_speed) {
  std::vector<std::unique_ptr<Term>> terms;
  const bool wcsph = scheme_traits(scene.scheme).weakly_compressible;
  const auto& density = density_modes().at(scene.density_mode);
  const bool density_in_state = density.traits.adds_state("density");
  if (!density_in_state) terms.push_back(build(density, scene));  // before the terms that read rho
  // Basa et al. 2008 §4: corrected kernel gradients for the pressure and viscous terms.
  if (const auto& part = kernel_corrections().at(scene.kernel_correction); part.make) terms.push_back(build(part, scene));
  if (wcsph) {
    for (auto& t : equations_of_state().at(scene.equation_of_state).make(scene, sound_speed)) terms.push_back(std::move(t));
    if (scene.pressure_reduction) terms.push_back(make_pressure_reduction());  // Basa eq. 20
    terms.push_back(build(pressure_gradients().at(scene.pressure_gradient), scene));
    if (density_in_state) terms.push_back(build(density, scene));  // a rate: Szewc eq. 19
    if (const auto& part = density_diffusions().at(scene.density_diffusion); part.make)
      for (auto& t : part.make(scene, sound_speed)) terms.push_back(std::move(t));
  }
  // Particle regularisation: a velocity in dr/dt and the corrections of the carried fields.
  if (const auto& part = regularisations().at(scene.regularisation); part.make) terms.push_back(build(part, scene));
  if (scene.viscosity > 0) terms.push_back(build(viscosity_models().at(scene.viscosity_model), scene));
  // The components of g the pressure takes (rhs/pressure_gravity.hpp) are not a term.
  const std::vector<std::string> force = momentum_body_force(scene);
  if (!is_zero_force(force)) terms.push_back(make_body_force(force));
  if (const auto& part = wall_forces().at(scene.wall_force); part.make) terms.push_back(build(part, scene));
  return terms;
}

}  // namespace arksph
