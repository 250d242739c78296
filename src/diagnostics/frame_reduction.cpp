#include "diagnostics/frame_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/expression.hpp"
#include "diagnostics/poiseuille.hpp"
#include "kernels/kernel.hpp"
#include "projection/divergence_operator.hpp"

namespace arksph {

namespace {
// The blocks of sums_ before the optional ones: kinetic energy, C&R eq. 24's numerator and
// denominator sums, sum m d (Szewc eq. 55), sum d0, the particle count, and the volume-weighted
// sum of (D u)^2 with its volume.
enum Sum { kKinetic, kDeviation2, kRatio, kDensity, kInitial, kCount, kDivergence2, kVolume, kBase };
enum Max { kSpeed, kPeak, kPeakExact, kMaxima };

double lid_speed(const Scene& s) { return std::hypot(s.sides[3].velocity[0], s.sides[3].velocity[1]); }
// The Poiseuille half-width and centre of the scene's channel.
double half_width(const Scene& s) { return 0.5 * (s.max[1] - s.min[1]); }
double centre(const Scene& s) { return 0.5 * (s.max[1] + s.min[1]); }
}  // namespace

FrameReduction::FrameReduction(const Scene& scene, double sound_speed)
    : scene_(scene),
      ghia_kernel_(ghia_interpolation_kernel(scene.spacing)),
      grid_(scene.interface ? IndicatorGrid(scene.min[0], scene.min[1], scene.max[0], scene.max[1], scene.spacing)
                            : IndicatorGrid(0, 0, 0, 0, 1)),
      exact_(scene.exact_velocity),
      energy_(scene, sound_speed) {
  std::size_t at = kBase;
  ghia_at_ = at;
  if (scene.ghia_re) {
    ghia_points_ = ghia_points(scene.min[0], scene.min[1], scene.max[0] - scene.min[0]);
    at += 3 * ghia_points_.size();
  }
  poiseuille_at_ = at;
  if (scene.poiseuille) at += 1;
  grid_at_ = at;
  if (scene.interface) at += grid_.num.size() + grid_.den.size();
  upper_at_ = at;
  if (scene.interface) at += 2;  // sum m d and the count over the upper phase
  exact_at_ = at;
  if (exact_.enabled()) at += 4;
  energy_at_ = at;
  if (energy_.enabled()) at += 2;  // E_p, E_c
  nearest_at_ = at;
  bins_ = nearest_neighbor_histogram_of(FluidFields{}, 0, 1.0).counts.size();  // its bins (no particles)
  at += bins_;
  sums_.assign(at, 0.0);
  max_.assign(kMaxima, 0.0);
}

void FrameReduction::add(const FrameParticles& p, const std::function<bool(double, double)>& owns) {
  const FluidFields& f = *p.f;
  const std::size_t n = p.n;
  const bool two_d = f.dim == 2;
  // Number density d_a = sum_b W_ab, self and ghosts included (C&R eq. 25; flow_metrics.hpp).
  d_.assign(n, 0.0);
  mass_.assign(f.m.begin(), f.m.begin() + static_cast<long>(n));
  const double w_self = f.kernel->W(0.0);
  for (std::size_t a = 0; a < n; ++a) {
    double s = w_self;
    f.pairs.for_pairs(a, [&](std::uint32_t, double, double, double, double w, double) { s += w; });
    d_[a] = s;
  }
  std::vector<double> div(f.n_real);
  difference_divergence(f, f.u.data(), two_d ? f.v.data() : nullptr, div.data());
  for (std::size_t a = 0; a < n; ++a) {
    const double speed2 = f.u[a] * f.u[a] + (two_d ? f.v[a] * f.v[a] : 0.0);
    sums_[kKinetic] += 0.5 * f.m[a] * speed2;
    max_[kSpeed] = std::max(max_[kSpeed], std::sqrt(speed2));
    sums_[kDeviation2] += (d_[a] - p.d0[a]) * (d_[a] - p.d0[a]);  // C&R eq. 24, numerator
    sums_[kRatio] += d_[a] / p.d0[a];                               // C&R eq. 24, denominator
    sums_[kDensity] += f.m[a] * d_[a];                               // Szewc eq. 55
    sums_[kInitial] += p.d0[a];
    const double vol = f.m[a] / f.rho[a];
    sums_[kDivergence2] += vol * div[a] * div[a];
    sums_[kVolume] += vol;
  }
  sums_[kCount] += static_cast<double>(n);
  for (std::size_t i = 0; i < ghia_points_.size(); ++i) {
    const auto& q = ghia_points_[i];
    if (!owns(q[0], q[1])) continue;
    const std::array<double, 3> s = shepard_sums(f, ghia_kernel_, q[0], q[1], f.n_real);
    for (int k = 0; k < 3; ++k) sums_[ghia_at_ + 3 * i + static_cast<std::size_t>(k)] += s[static_cast<std::size_t>(k)];
  }
  if (scene_.poiseuille && f.t > 0) {
    const double d = half_width(scene_), yc = centre(scene_), g = poiseuille_force(scene_);
    for (std::size_t a = 0; a < n; ++a) {
      const double exact = poiseuille_velocity(f.y[a] - yc, f.t, d, scene_.viscosity, g);
      const double rel = (f.u[a] - exact) / exact;
      sums_[poiseuille_at_] += rel * rel;
    }
  }
  if (scene_.poiseuille) {
    profile_.clear();
    for (std::size_t a = 0; a < n; ++a) profile_.insert(profile_.end(), {f.y[a], f.u[a]});
  }
  if (scene_.interface) {
    IndicatorGrid g = grid_;
    add_phase_indicator(f, p.phase, g, owns);
    const std::size_t nodes = g.num.size();
    for (std::size_t k = 0; k < nodes; ++k) {
      sums_[grid_at_ + k] += g.num[k];
      sums_[grid_at_ + nodes + k] += g.den[k];
    }
    phase_.assign(p.phase, p.phase + n);
    for (std::size_t a = 0; a < n; ++a) {  // Szewc eq. 55 over the upper phase (eq. 56: pass 2)
      if (p.phase[a] < 1) continue;
      sums_[upper_at_] += f.m[a] * d_[a];
      sums_[upper_at_ + 1] += 1;
    }
  }
  if (exact_.enabled()) {
    const ExactVelocity::Sums s = exact_.sums(f, n);
    sums_[exact_at_] += s.err;
    sums_[exact_at_ + 1] += s.norm;
    sums_[exact_at_ + 2] += s.fit;
    sums_[exact_at_ + 3] += s.fit_norm;
    max_[kPeak] = std::max(max_[kPeak], s.peak);
    max_[kPeakExact] = std::max(max_[kPeakExact], s.peak_exact);
  }
  if (energy_.enabled()) {
    const std::array<double, 2> e = energy_.sums(f, n);
    sums_[energy_at_] += e[0];
    sums_[energy_at_ + 1] += e[1];
  }
  const Histogram h = nearest_neighbor_histogram_of(f, n, scene_.spacing);
  for (std::size_t k = 0; k < bins_; ++k) sums_[nearest_at_ + k] += static_cast<double>(h.counts[k]);
}

std::vector<double> FrameReduction::fluctuations() const {
  const double mean = sums_[kDensity] / sums_[kCount];
  const double upper_mean = scene_.interface && sums_[upper_at_ + 1] > 0 ? sums_[upper_at_] / sums_[upper_at_ + 1] : 0.0;
  double all = 0, upper = 0;
  for (std::size_t a = 0; a < d_.size(); ++a) {
    const double rho_a = mass_[a] * d_[a];
    all += (rho_a - mean) * (rho_a - mean);  // Szewc eq. 56
    if (!phase_.empty() && phase_[a] >= 1) upper += (rho_a - upper_mean) * (rho_a - upper_mean);
  }
  return {all, upper};
}

FrameDiagnostics FrameReduction::finish(double t, const std::vector<double>& fluctuations) const {
  FrameDiagnostics out;
  out.t = t;
  const double n = sums_[kCount];
  FlowMetrics& m = out.metrics;
  m.kinetic_energy = sums_[kKinetic];
  m.max_speed = max_[kSpeed];
  // C&R eq. 24 as printed: sqrt(mean (d - d0)^2) / mean(d / d0), the numerator divided by the mean
  // initial number density so that CV is a relative figure (flow_metrics.hpp).
  m.cv = std::sqrt(sums_[kDeviation2] / n) / (sums_[kInitial] / n) / (sums_[kRatio] / n);
  m.density_mean = sums_[kDensity] / n;
  m.density_rms = std::sqrt(fluctuations[0] / n);
  out.divergence_rms = std::sqrt(sums_[kDivergence2] / sums_[kVolume]);
  if (scene_.ghia_re) {
    std::vector<double> u, v;
    const std::size_t nu = ghia_u_point_count();
    for (std::size_t i = 0; i < ghia_points_.size(); ++i) {
      const double* s = &sums_[ghia_at_ + 3 * i];
      (i < nu ? u : v).push_back(shepard_ratio(i < nu ? s[0] : s[1], s[2]));
    }
    out.ghia = ghia_errors_at(scene_.ghia_re, lid_speed(scene_), u, v);
  }
  if (scene_.poiseuille) out.poiseuille_profile = profile_;  // a decomposed run joins the processes' own
  if (scene_.poiseuille)
    out.poiseuille_eps = t > 0 ? std::sqrt(sums_[poiseuille_at_] / n) : std::numeric_limits<double>::quiet_NaN();
  if (scene_.interface) {
    IndicatorGrid g = grid_;
    const std::size_t nodes = g.num.size();
    std::copy(sums_.begin() + static_cast<long>(grid_at_), sums_.begin() + static_cast<long>(grid_at_ + nodes),
              g.num.begin());
    std::copy(sums_.begin() + static_cast<long>(grid_at_ + nodes),
              sums_.begin() + static_cast<long>(grid_at_ + 2 * nodes), g.den.begin());
    out.interface = contour_phase_indicator(g);
    const double count = sums_[upper_at_ + 1];
    if (count > 0) {
      out.upper_density.mean = sums_[upper_at_] / count;
      out.upper_density.rms = std::sqrt(fluctuations[1] / count);
    }
  }
  if (exact_.enabled()) {
    ExactVelocity::Sums s;
    s.err = sums_[exact_at_];
    s.norm = sums_[exact_at_ + 1];
    s.fit = sums_[exact_at_ + 2];
    s.fit_norm = sums_[exact_at_ + 3];
    s.peak = max_[kPeak];
    s.peak_exact = max_[kPeakExact];
    out.exact = ExactVelocity::errors_from(s);
  }
  if (energy_.enabled()) {
    out.potential_energy = sums_[energy_at_];
    out.compressible_energy = sums_[energy_at_ + 1];
  }
  const Histogram shape = nearest_neighbor_histogram_of(FluidFields{}, 0, scene_.spacing);
  out.nearest.bin_width = shape.bin_width;
  for (std::size_t k = 0; k < bins_; ++k) out.nearest.counts.push_back(static_cast<long>(sums_[nearest_at_ + k]));
  return out;
}

}  // namespace arksph
