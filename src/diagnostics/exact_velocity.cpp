#include "diagnostics/exact_velocity.hpp"

#include <algorithm>
#include <cmath>

namespace arksph {

ExactVelocity::ExactVelocity(const std::vector<std::string>& components) {
  for (const auto& c : components) {
    components_.emplace_back(c, std::vector<std::string>{"x", "y", "t"});
    if (!components_.back().is_constant() || components_.back().eval(0, 0, 0) != 0.0) enabled_ = true;
  }
}

ExactVelocityErrors ExactVelocity::errors(const FluidFields& f) const {
  double err = 0, norm = 0, peak = 0, peak_exact = 0, fit = 0, fit_norm = 0;
  const bool two_d = f.dim == 2 && components_.size() > 1;
  for (std::size_t a = 0; a < f.n_real; ++a) {
    const double y = two_d ? f.y[a] : 0.0;
    const double ue = components_[0].eval(f.x[a], y, f.t);
    const double ve = two_d ? components_[1].eval(f.x[a], y, f.t) : 0.0;
    const double v = two_d ? f.v[a] : 0.0;
    err += std::hypot(f.u[a] - ue, v - ve);
    const double exact = std::hypot(ue, ve);
    norm += exact;
    peak = std::max(peak, std::hypot(f.u[a], v));
    peak_exact = std::max(peak_exact, exact);
    const double vol = f.m[a] / f.rho[a];
    fit += vol * (f.u[a] * ue + v * ve);
    fit_norm += vol * exact * exact;
  }
  ExactVelocityErrors e;
  e.l1_relative = norm > 0 ? err / norm : NAN;
  e.peak_speed_error = peak_exact > 0 ? peak / peak_exact - 1.0 : NAN;
  e.amplitude_error = fit_norm > 0 ? fit / fit_norm - 1.0 : NAN;
  return e;
}

}  // namespace arksph
