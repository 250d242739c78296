// Assembles the right-hand side from the scene: parts by name from the registries, and the rules
// that leave out what a scene does not need.
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/expression.hpp"
#include "core/scheme.hpp"
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
  double u_ref = max_initial_speed;
  for (int s = 0; s < 2 * scene.dimension; ++s)
    u_ref = std::max(u_ref, std::hypot(scene.sides[s].velocity[0], scene.sides[s].velocity[1]));
  double length = 0, force = 0;
  for (int k = 0; k < scene.dimension; ++k) {
    length = std::max(length, scene.max[k] - scene.min[k]);
    Expression e(scene.body_force.at(k), {"x", "y", "t"});
    force = std::max(force, std::abs(e.eval(0.5 * (scene.min[0] + scene.max[0]),
                                            0.5 * (scene.min[1] + scene.max[1]), 0.0)));
  }
  u_ref = std::max(u_ref, std::sqrt(force * length));
  return u_ref > 0 ? 10.0 * u_ref : 1.0;
}

std::vector<std::unique_ptr<Term>> terms_from_scene(const Scene& scene, double sound_speed) {
  std::vector<std::unique_ptr<Term>> terms;
  const bool wcsph = scheme_traits(scene.scheme).weakly_compressible;
  if (scene.density_mode == "summation") terms.push_back(make_density_summation());
  // Basa et al. 2008 §4: corrected kernel gradients for the pressure and viscous terms.
  if (const auto& part = kernel_corrections().at(scene.kernel_correction); part.make) terms.push_back(build(part, scene));
  if (wcsph) {
    if (scene.equation_of_state == "ideal_gas") {
      terms.push_back(make_eos_ideal_gas(scene.gas_gamma));
      terms.push_back(make_energy_equation());
    } else {
      terms.push_back(make_eos_tait(sound_speed, scene.tait_gamma, scene.background_pressure));
    }
    if (scene.pressure_reduction) terms.push_back(make_pressure_reduction());  // Basa eq. 20
    terms.push_back(build(pressure_gradients().at(scene.pressure_gradient), scene));
    if (scene.density_mode == "continuity") terms.push_back(make_continuity());
  }
  if (scene.viscosity > 0) terms.push_back(build(viscosity_models().at(scene.viscosity_model), scene));
  if (!is_zero_force(scene.body_force)) terms.push_back(make_body_force(scene.body_force));
  return terms;
}

}  // namespace arksph
