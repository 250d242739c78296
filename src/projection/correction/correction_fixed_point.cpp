// Szewc et al. 2012's fixed point for the P-W correction (method.correction_solver = "fixed_point"):
// up to method.correction_max_iterations times, eq. 58 solved as a Poisson equation and the shift of
// eq. 57 applied, while the density fluctuation stays above the threshold. Eq. 58 is discretised
// with the approximate Laplacian of C&R eq. 19 at rho^n = rho0 (the PPE of the domain's Poisson
// back-end with the source 1 - rho~/rho0 less its mean, dt = 1), ghosts carrying their source's p*
// (Neumann walls); the gradient of eq. 57 is the difference form sum_b V_b (p*_b - p*_a) grad_a W_ab,
// which vanishes for a constant p* (correction_newton.hpp: correction_shift).
#include <memory>

#include "projection/correction/correction_newton.hpp"
#include "projection/correction/correction_solver.hpp"
#include "core/particle_order.hpp"

namespace arksph {

namespace {

class FixedPointCorrection : public CorrectionSolver {
 public:
  FixedPointCorrection(const Scene& scene, ParticleDomain& domain)
      : domain_(domain),
        poisson_(domain.poisson(scene, false)),
        threshold_(scene.correction_threshold),
        max_iterations_(scene.correction_max_iterations) {}

  CorrectionOutcome correct(double t, double* y, std::vector<double>& s, double error,
                            std::vector<double>* history) override {
    CorrectionOutcome out{error, 0};
    for (int it = 0; it < max_iterations_ && out.error > threshold_; ++it) {
      if (it > 0 && history) history->push_back(out.error);
      step(s, y);
      ++out.iterations;
      // The error after the shift decides whether to go on; after the last allowed solve it is only
      // wanted for the recorded history (one right-hand-side evaluation saved per step otherwise).
      if (it + 1 < max_iterations_ || history) {
        domain_.refresh(t, y);
        out.error = density_fluctuation(domain_.fields(), domain_.correction_span(), s);
      }
    }
    return out;
  }

  void forget_warm_start() override {
    pstar_.clear();
    poisson_->reset();
  }
  void permute_particles(const std::vector<std::uint32_t>& from) override {
    permute(pstar_, from);
    poisson_->reset();  // its stored structure is in the old order
  }

 private:
  // Eq. 58 solved (warm-started from the last p*), then eq. 57: r_a -= grad p*_a / rho0, with the
  // halo copies' p* their owners'.
  void step(const std::vector<double>& s, double* y) {
    const StateLayout L = domain_.layout();
    const FluidFields& f = domain_.fields();
    poisson_->solve(f, s, 1.0, pstar_);
    std::vector<double> dx, dy;
    correction_shift(f, domain_.with_halo(pstar_), dx, dy, L.n);
    for (std::size_t a = 0; a < L.n; ++a) {
      y[L.pos(0) + a] += dx[a];
      if (L.dim == 2) y[L.pos(1) + a] += dy[a];
    }
  }

  ParticleDomain& domain_;
  std::unique_ptr<ParticlePoisson> poisson_;
  double threshold_;
  int max_iterations_;
  std::vector<double> pstar_;  // the last solution: the next warm start
};

}  // namespace

std::unique_ptr<CorrectionSolver> make_correction_fixed_point(const Scene& scene, ParticleDomain& domain) {
  return std::make_unique<FixedPointCorrection>(scene, domain);
}

}  // namespace arksph
