// The energy budget of metrics.energy_budget (docs/methods/energy-budget.md), for a flow under a
// constant body force g (none: g = 0), per unit depth in 2D as the masses are:
//   E_k = sum_a m_a |u_a|^2 / 2                     (timeseries.csv kinetic_energy)
//   E_p = - sum_a m_a g . r_a
//   E_c = sum_a m_a e(rho_a), de/drho = p / rho^2   (WCSPH; Tait: rhs/pressure/tait_energy.hpp;
//                                                   ideal gas: e is the state's; projection schemes: 0)
//   W_visc = - int_0^t sum_a m_a u_a . a_visc,a dt  (diagnostics/viscous_dissipation.hpp)
//   E = E_k + E_p + E_c + W_visc, constant up to the time-integration error and what the other
//   terms of f do not conserve (Antuono et al. 2015).
// EnergyBudget gives E_p and E_c as sums over particles, which add up over the ranks of a
// decomposed run (diagnostics/frame_reduction.hpp carries them).
#pragma once
#include <array>
#include <cstddef>

#include "core/scene.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

class EnergyBudget {
 public:
  // sound_speed: the run's resolved WCSPH sound speed (Tait). Off unless scene.energy_budget.
  EnergyBudget(const Scene& scene, double sound_speed);
  bool enabled() const { return enabled_; }
  // {E_p, E_c} of the first n real particles of fresh fields f.
  std::array<double, 2> sums(const FluidFields& f, std::size_t n) const;

 private:
  enum class Compressible { none, tait, internal_energy };
  bool enabled_ = false;
  double g_[2] = {0, 0};
  Compressible compressible_ = Compressible::none;
  double sound_speed_ = 0, gamma_ = 7, background_ = 0;
};

// The body force of a scene is constant: no component depends on x, y or t.
bool constant_body_force(const Scene& scene);

}  // namespace arksph
