#include "projection/correction/density_relaxation.hpp"

#include <cmath>


namespace arksph {

namespace {
// Largest shift of a particle as a fraction of the spacing (the linearisation holds for shifts small
// against the kernel radius), the same as the step-wise Newton correction's clip.
constexpr double kMaxShift = 0.1;
}  // namespace

DensityRelaxation::DensityRelaxation(const Scene& scene, double rate)
    : rate_(rate), cap_(kMaxShift * scene.spacing) {}

int DensityRelaxation::add_velocity(const FluidFields& f, const CorrectionSpan& span, double* xdot, double* ydot) {
  const std::size_t n = span.own;
  last_error_ = density_fluctuation(f, span, s_);
  const int iterations = newton_shift(f, span, s_, p_, dx_, dy_);
  const double inv_cap2 = 1.0 / (cap_ * cap_);
  for (std::size_t a = 0; a < n; ++a) {
    const double len2 = dx_[a] * dx_[a] + (ydot ? dy_[a] * dy_[a] : 0.0);
    if (!std::isfinite(len2)) continue;  // a failed solve leaves the particle alone
    const double k = rate_ / std::sqrt(1.0 + len2 * inv_cap2);
    xdot[a] += k * dx_[a];
    if (ydot) ydot[a] += k * dy_[a];
  }
  return iterations;
}

}  // namespace arksph
