#include "distributed/halo_density_correction.hpp"

#include <chrono>

#include "core/particle_order.hpp"

namespace arksph::distributed {

HaloDensityCorrection::HaloDensityCorrection(const Scene& scene, ParticleDomain& domain, HaloRhs& f,
                                             const RankParticles& owned)
    : domain_(domain),
      f_(f),
      owned_(owned),
      threshold_(scene.correction_threshold),
      max_iterations_(scene.correction_max_iterations),
      spacing_(scene.spacing),
      newton_(scene.correction_solver == "newton"),
      poisson_(domain.poisson(scene, false)) {}

void HaloDensityCorrection::forget_warm_start() {
  pstar_.clear();
  poisson_->reset();
}

void HaloDensityCorrection::permute_particles(const std::vector<std::uint32_t>& from) {
  permute(pstar_, from);
  poisson_->reset();
}

void HaloDensityCorrection::fixed_point_step(const std::vector<double>& s, double* y) {
  const StateLayout L = owned_.layout();
  const std::size_t n = L.n;
  // Eq. 58 with the Laplacian of C&R eq. 19 at rho = rho0: the PPE's rows with the source 1 -
  // rho~/rho0 in place of div u* and dt = 1 (as one process's assemble_ppe(f, source, 1.0)).
  poisson_->solve(f_.evaluator().fields(), s, 1.0, pstar_);
  ++stats_.iterations;
  // Eq. 57: r_a -= grad p*_a / rho0, the gradient in difference form with the copies' p* their owners'.
  std::vector<double> dx, dy;
  correction_shift(f_.evaluator().fields(), domain_.with_halo(pstar_), dx, dy, n);
  for (std::size_t a = 0; a < n; ++a) {
    y[L.pos(0) + a] += dx[a];
    if (L.dim == 2) y[L.pos(1) + a] += dy[a];
  }
}

void HaloDensityCorrection::apply(double t, double* y) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool record = stats_.applications == 0;
  f_.eval(t, y, nullptr);
  std::vector<double> s;
  double error = density_fluctuation(f_.evaluator().fields(), domain_.correction_span(), s);
  if (error <= threshold_) return;
  ++stats_.applications;
  if (record) stats_.first_history.push_back(error);
  if (newton_) {
    const NewtonCorrectionResult r = correct_density_newton(
        [&](const double* state) { f_.eval(t, state, nullptr); },
        [&]() -> const FluidFields& { return f_.evaluator().fields(); }, [&] { return domain_.correction_span(); }, owned_.layout(), y,
        max_iterations_, threshold_, spacing_);
    stats_.iterations += r.iterations;
    error = r.error;
  } else {
    for (int it = 0; it < max_iterations_ && error > threshold_; ++it) {
      if (it > 0 && record) stats_.first_history.push_back(error);
      fixed_point_step(s, y);
      // The error after the shift decides whether to go on; after the last allowed solve it is
      // only wanted for the recorded history.
      if (it + 1 < max_iterations_ || record) {
        f_.eval(t, y, nullptr);
        error = density_fluctuation(f_.evaluator().fields(), domain_.correction_span(), s);
      }
    }
  }
  if (record) stats_.first_history.push_back(error);
  stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace arksph::distributed
