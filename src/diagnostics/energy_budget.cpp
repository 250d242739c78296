#include "diagnostics/energy_budget.hpp"

#include "core/expression.hpp"
#include "core/scheme.hpp"
#include "rhs/pressure/tait_energy.hpp"
#include "rhs/term_registry.hpp"

namespace arksph {

bool constant_body_force(const Scene& scene) {
  for (int k = 0; k < scene.dimension && k < static_cast<int>(scene.body_force.size()); ++k)
    if (!Expression(scene.body_force[static_cast<std::size_t>(k)], {"x", "y", "t"}).is_constant()) return false;
  return true;
}

EnergyBudget::EnergyBudget(const Scene& scene, double sound_speed) : enabled_(scene.energy_budget) {
  if (!enabled_) return;
  for (int k = 0; k < scene.dimension && k < static_cast<int>(scene.body_force.size()); ++k)
    g_[k] = Expression(scene.body_force[static_cast<std::size_t>(k)], {"x", "y", "t"}).eval(0, 0, 0);
  if (!scheme_traits(scene.scheme).weakly_compressible) return;  // incompressible: no E_c
  // The specific energy is a state of its own (ideal gas, Basa eq. 14), or Tait's e(rho).
  if (equations_of_state().at(scene.equation_of_state).traits.adds_state("energy"))
    compressible_ = Compressible::internal_energy;
  else if (equations_of_state().at(scene.equation_of_state).traits.tait)
    compressible_ = Compressible::tait;
  sound_speed_ = sound_speed;
  gamma_ = scene.tait_gamma;
  background_ = scene.background_pressure;
}

std::array<double, 2> EnergyBudget::sums(const FluidFields& f, std::size_t n) const {
  double potential = 0, compressible = 0;
  const bool two_d = f.dim == 2;
  for (std::size_t a = 0; a < n; ++a) {
    potential -= f.m[a] * (g_[0] * f.x[a] + (two_d ? g_[1] * f.y[a] : 0.0));
    if (compressible_ == Compressible::tait)
      compressible += f.m[a] * tait_specific_energy(f.rho[a], f.rho0[a], sound_speed_, gamma_, background_);
    else if (compressible_ == Compressible::internal_energy)
      compressible += f.m[a] * f.e[a];
  }
  return {potential, compressible};
}

}  // namespace arksph
