// Assembles the right-hand side from the scene: registries by name (one line each) and the rules
// that leave out what a scene does not need.
#include <algorithm>
#include <cmath>
#include <utility>

#include "io/expression.hpp"
#include "rhs/terms.hpp"

namespace arksph {
namespace {
using Factory = std::unique_ptr<Term> (*)(const Scene&);

const std::vector<std::pair<std::string, Factory>>& viscosity_table() {
  static const std::vector<std::pair<std::string, Factory>> table = {
      {"morris", [](const Scene&) { return make_viscosity_morris(); }},      // Basa et al. eq. 35 (model E)
      {"monaghan", [](const Scene&) { return make_viscosity_monaghan(); }},  // Szewc et al. eq. 24, C&R eq. 2
      {"direct", [](const Scene&) { return make_viscosity_direct(); }},      // Basa et al. eqs. 27-28 (model A)
      {"two_pass", [](const Scene&) { return make_viscosity_two_pass(); }},  // Basa et al. eq. 29 (model B)
      {"violeau", [](const Scene&) { return make_viscosity_violeau(); }},    // Basa et al. eq. 33 (model C)
      {"cleary", [](const Scene& s) { return make_viscosity_cleary(s.cleary_xi); }},  // Basa et al. eq. 34 (model D)
  };
  return table;
}

const std::vector<std::pair<std::string, Factory>>& pressure_gradient_table() {
  static const std::vector<std::pair<std::string, Factory>> table = {
      {"colagrossi", [](const Scene&) { return make_pressure_gradient_colagrossi(); }},  // Szewc et al. eq. 23
      {"monaghan", [](const Scene&) { return make_pressure_gradient_monaghan(); }},      // C&R eq. 1
  };
  return table;
}

template <class Table>
std::vector<std::string> names_of(const Table& t) {
  std::vector<std::string> n;
  for (const auto& e : t) n.push_back(e.first);
  return n;
}

template <class Table>
std::unique_ptr<Term> make_named(const Table& t, const std::string& name, const Scene& scene) {
  for (const auto& [n, make] : t)
    if (n == name) return make(scene);
  throw std::out_of_range("unknown model '" + name + "'");
}

bool is_zero_force(const std::vector<std::string>& expr) {
  for (const auto& e : expr) {
    Expression ex(e, {"x", "y", "t"});
    if (!ex.is_constant() || ex.eval(0, 0, 0) != 0.0) return false;
  }
  return true;
}
}  // namespace

std::vector<std::string> viscosity_model_names() { return names_of(viscosity_table()); }
std::vector<std::string> pressure_gradient_names() { return names_of(pressure_gradient_table()); }
std::vector<std::string> kernel_correction_names() { return {"none", "shepard", "bonet_lok"}; }

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
  const bool wcsph = scene.scheme == "wcsph";
  if (scene.density_mode == "summation") terms.push_back(make_density_summation());
  // Basa et al. 2008 §4: corrected kernel gradients for the pressure and viscous terms.
  if (scene.kernel_correction != "none") terms.push_back(make_kernel_correction(scene.kernel_correction));
  if (wcsph) {
    if (scene.equation_of_state == "ideal_gas") {
      terms.push_back(make_eos_ideal_gas(scene.gas_gamma));
      terms.push_back(make_energy_equation());
    } else {
      terms.push_back(make_eos_tait(sound_speed, scene.tait_gamma, scene.background_pressure));
    }
    if (scene.pressure_reduction) terms.push_back(make_pressure_reduction());  // Basa eq. 20
    terms.push_back(make_named(pressure_gradient_table(), scene.pressure_gradient, scene));
    if (scene.density_mode == "continuity") terms.push_back(make_continuity());
  }
  if (scene.viscosity > 0) terms.push_back(make_named(viscosity_table(), scene.viscosity_model, scene));
  if (!is_zero_force(scene.body_force)) terms.push_back(make_body_force(scene.body_force));
  return terms;
}

}  // namespace arksph
