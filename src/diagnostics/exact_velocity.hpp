// Velocity errors against an exact velocity field u(x, y, t) given in the scene (metrics.exact_velocity),
// for flows with a known solution such as the periodic Taylor-Green vortex.
#pragma once
#include <string>
#include <vector>

#include "core/expression.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

struct ExactVelocityErrors {
  // Relative L1 error sum_a |u_a - u_exact(r_a, t)| / sum_a |u_exact(r_a, t)| (vector magnitudes).
  double l1_relative = 0;
  // Error of the peak speed: max_a |u_a| / max_a |u_exact(r_a, t)| - 1 (negative: too much decay).
  double peak_speed_error = 0;
  // Error of the vortex's amplitude: the least-squares multiple a of the exact field that fits the
  // computed one, a = sum_a V_a u_a . u_exact,a / sum_a V_a |u_exact,a|^2 (V_a = m_a / rho_a: the
  // discrete integrals over the fluid), minus 1. For a decaying mode (Taylor-Green) a - 1 is the error
  // of its decay, as peak_speed_error is, but it reads every particle rather than the fastest one, so
  // particle noise (orthogonal to the mode) and the lattice's sampling of the peak do not enter it.
  double amplitude_error = 0;
};

class ExactVelocity {
 public:
  // One expression of x, y, t per dimension. All "0" means no exact field (enabled() is false).
  explicit ExactVelocity(const std::vector<std::string>& components);
  bool enabled() const { return enabled_; }
  // Over the real particles of fresh fields.
  ExactVelocityErrors errors(const FluidFields& f) const;
  // The same in two parts, for sums gathered elsewhere (a decomposed run): the sums over the real
  // particles [0, n) of f, which add up (err .. fit_norm) or take the largest (peak, peak_exact)
  // over disjoint sets of particles, and the errors from their totals.
  struct Sums {
    double err = 0, norm = 0, fit = 0, fit_norm = 0;  // sum |u - u_e|, |u_e|, V u . u_e, V |u_e|^2
    double peak = 0, peak_exact = 0;                  // max |u|, |u_e|
  };
  Sums sums(const FluidFields& f, std::size_t n) const;
  static ExactVelocityErrors errors_from(const Sums& s);

 private:
  std::vector<Expression> components_;
  bool enabled_ = false;
};

}  // namespace arksph
