#include "projection/correction/DensityCorrection_PozorskiWawrenczuk.hpp"

#include <chrono>

#include "core/param_builder.hpp"
#include "projection/correction/correction_newton.hpp"

namespace arksph {

const Registry<Selected>& density_corrections() {
  static const Registry<Selected> r("density_correction", "method.density_correction", {
      {"none", "no position correction"},
      {"pozorski_wawrenczuk", "positions shifted so that the summation density returns to rho0 (Szewc et al. 2012 §9, eqs. 57-58)", {},
       {number("method.correction_threshold", 1e-3).in(at_least(0))
            .doc("r.m.s. relative density error that triggers the correction").to(&Scene::correction_threshold),
        whole("method.correction_max_iterations", 1).in(between(1, 1000))
            .doc("correction solves per step at most (Szewc: 1)").to(&Scene::correction_max_iterations),
        choice("method.correction_solver", "auto").family("correction_solver")
            .doc("solver of the correction's Poisson problem").to(&Scene::correction_solver),
        number("method.correction_relaxation", 1.0).in(above(0))
            .doc("constrained projection: the correction is the velocity kappa dr inside f (dr of eqs. 57-58), "
                 "kappa = this x U/h, the decay rate of density fluctuations; the keys above apply after a step only")
            .to(&Scene::correction_relaxation)},
       {.schemes = {"isph", "isph-gpps"}, .corrects_density = true}},
  });
  return r;
}

DensityCorrection::DensityCorrection(const Scene& scene, ParticleDomain& domain)
    : domain_(domain),
      solver_(correction_solvers().at(scene.correction_solver).make(scene, domain)),
      threshold_(scene.correction_threshold) {}

void DensityCorrection::permute_particles(const std::vector<std::uint32_t>& from) { solver_->permute_particles(from); }

void DensityCorrection::forget_warm_start() { solver_->forget_warm_start(); }

void DensityCorrection::apply(double t, double* y) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool record = stats_.applications == 0;
  // The r.m.s. fluctuation of rho~/rho0 about its mean (Szewc eq. 56): the kernel's bias on a
  // perfect lattice (Wendland +0.12 % at h = 2 dx) is a constant the correction cannot and need not remove.
  domain_.refresh(t, y);
  std::vector<double> s;
  const double error = density_fluctuation(domain_.fields(), domain_.correction_span(), s);
  if (error <= threshold_) return;
  ++stats_.applications;
  if (record) stats_.first_history.push_back(error);
  const CorrectionOutcome out = solver_->correct(t, y, s, error, record ? &stats_.first_history : nullptr);
  stats_.iterations += out.iterations;
  if (record) stats_.first_history.push_back(out.error);
  stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace arksph
