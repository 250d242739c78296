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

ExactVelocity::Sums ExactVelocity::sums(const FluidFields& f, std::size_t n) const {
  Sums s;
  const bool two_d = f.dim == 2 && components_.size() > 1;
  for (std::size_t a = 0; a < n; ++a) {
    const double y = two_d ? f.y[a] : 0.0;
    const double ue = components_[0].eval(f.x[a], y, f.t);
    const double ve = two_d ? components_[1].eval(f.x[a], y, f.t) : 0.0;
    const double v = two_d ? f.v[a] : 0.0;
    s.err += std::hypot(f.u[a] - ue, v - ve);
    const double exact = std::hypot(ue, ve);
    s.norm += exact;
    s.peak = std::max(s.peak, std::hypot(f.u[a], v));
    s.peak_exact = std::max(s.peak_exact, exact);
    const double vol = f.m[a] / f.rho[a];
    s.fit += vol * (f.u[a] * ue + v * ve);
    s.fit_norm += vol * exact * exact;
  }
  return s;
}

ExactVelocityErrors ExactVelocity::errors_from(const Sums& s) {
  ExactVelocityErrors e;
  e.l1_relative = s.norm > 0 ? s.err / s.norm : NAN;
  e.peak_speed_error = s.peak_exact > 0 ? s.peak / s.peak_exact - 1.0 : NAN;
  e.amplitude_error = s.fit_norm > 0 ? s.fit / s.fit_norm - 1.0 : NAN;
  return e;
}

ExactVelocityErrors ExactVelocity::errors(const FluidFields& f) const { return errors_from(sums(f, f.n_real)); }

}  // namespace arksph
