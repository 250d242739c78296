#include "diagnostics/flow_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/kernel.hpp"

namespace arksph {

std::vector<double> number_density(const FluidFields& f) {
  std::vector<double> d(f.n_real);
  const double w_self = f.kernel->W(0.0);
  for (std::size_t a = 0; a < f.n_real; ++a) {
    double s = w_self;
    f.pairs.for_pairs(a, [&](std::uint32_t, double, double, double, double w, double) { s += w; });
    d[a] = s;
  }
  return d;
}

FlowMetrics flow_metrics(const FluidFields& f, const std::vector<double>& d0) {
  FlowMetrics m;
  const std::size_t n = f.n_real;
  const auto d = number_density(f);
  double sum_dev2 = 0, sum_ratio = 0, sum_rho = 0;
  for (std::size_t a = 0; a < n; ++a) {
    const double speed2 = f.u[a] * f.u[a] + (f.dim == 2 ? f.v[a] * f.v[a] : 0.0);
    m.kinetic_energy += 0.5 * f.m[a] * speed2;
    m.max_speed = std::max(m.max_speed, std::sqrt(speed2));
    sum_dev2 += (d[a] - d0[a]) * (d[a] - d0[a]);  // C&R eq. 24, numerator
    sum_ratio += d[a] / d0[a];                    // C&R eq. 24, denominator
    sum_rho += f.m[a] * d[a];                     // Szewc eq. 55
  }
  const double nn = static_cast<double>(n);
  // C&R eq. 24 as printed: sqrt(mean (d - d0)^2) / mean(d / d0). The numerator carries the units
  // of d; we divide it by the mean initial number density so that CV is a relative figure.
  double d0_mean = 0;
  for (double v : d0) d0_mean += v;
  d0_mean /= nn;
  m.cv = std::sqrt(sum_dev2 / nn) / d0_mean / (sum_ratio / nn);
  m.density_mean = sum_rho / nn;
  double sum_fluct2 = 0;
  for (std::size_t a = 0; a < n; ++a) {
    const double rho_a = f.m[a] * d[a];
    sum_fluct2 += (rho_a - m.density_mean) * (rho_a - m.density_mean);  // Szewc eq. 56
  }
  m.density_rms = std::sqrt(sum_fluct2 / nn);
  return m;
}

}  // namespace arksph
