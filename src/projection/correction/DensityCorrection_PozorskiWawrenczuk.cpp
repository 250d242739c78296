#include "projection/correction/DensityCorrection_PozorskiWawrenczuk.hpp"

#include <chrono>
#include <cmath>

#include "core/param_builder.hpp"
#include "core/particle_order.hpp"
#include "kernels/kernel.hpp"
#include "projection/correction/correction_kinsol.hpp"
#include "projection/correction/correction_newton.hpp"

namespace arksph {

const Registry<Selected>& correction_solvers() {
  static const Registry<Selected> r("correction_solver", "method.correction_solver", {
      {"fixed_point", "repeated linear solves of Szewc et al. 2012 eq. 58"},
      {"kinsol", "KINSOL Newton on eq. 59 with the Laplacian as frozen Jacobian (KLU)"},
      {"newton", "Newton with the exact Jacobian of the summation density"},
  });
  return r;
}

namespace {
// method.correction_solver = "auto": newton. With fixed steps of Szewc's single linear solve the
// density error grows wherever a step moves particles by more than one solve removes; the exact
// Jacobian removes most of it in one iteration. Measured at t = 10 on the spin-down: CV 0.0012
// against 0.0080 (C&R's set-up), 0.00037 against 0.013 (the project's defaults). Szewc's fixed
// point stays selectable and is what the paper cases use.
std::string automatic_correction_solver(const Scene&) { return "newton"; }
}  // namespace

const Registry<Selected>& density_corrections() {
  static const Registry<Selected> r("density_correction", "method.density_correction", {
      {"none", "no position correction"},
      {"pozorski_wawrenczuk", "positions shifted so that the summation density returns to rho0 (Szewc et al. 2012 §9, eqs. 57-58)", {},
       {number("method.correction_threshold", 1e-3).in(at_least(0))
            .doc("r.m.s. relative density error that triggers the correction").to(&Scene::correction_threshold),
        whole("method.correction_max_iterations", 1).in(between(1, 1000))
            .doc("correction solves per step at most (Szewc: 1)").to(&Scene::correction_max_iterations),
        choice("method.correction_solver", "auto").family("correction_solver")
            .doc("solver of the correction's Poisson problem; auto: newton")
            .automatic(automatic_correction_solver).to(&Scene::correction_solver),
        number("method.correction_relaxation", 1.0).in(above(0))
            .doc("constrained projection: the correction is the velocity kappa dr inside f (dr of eqs. 57-58), "
                 "kappa = this x U/h, the decay rate of density fluctuations; the keys above apply after a step only")
            .to(&Scene::correction_relaxation)},
       {.schemes = {"isph", "isph-gpps"}}},
  });
  return r;
}

DensityCorrection::DensityCorrection(const Scene& scene, ParticleDomain& domain)
    : domain_(domain),
      poisson_(domain.poisson(scene, false)),
      threshold_(scene.correction_threshold),
      max_iterations_(scene.correction_max_iterations),
      use_kinsol_(scene.correction_solver == "kinsol"),
      use_newton_(scene.correction_solver == "newton"),
      spacing_(scene.spacing) {}

void DensityCorrection::permute_particles(const std::vector<std::uint32_t>& from) {
  permute(pstar_, from);
  poisson_->reset();  // its stored structure is in the old order
}

void DensityCorrection::forget_warm_start() {
  pstar_.clear();
  poisson_->reset();
}

void DensityCorrection::fixed_point_step(const std::vector<double>& s, double* y) {
  const StateLayout L = domain_.layout();
  const std::size_t n = L.n;
  const FluidFields& f = domain_.fields();
  // Eq. 58 with the Laplacian of C&R eq. 19 at rho = rho0: the PPE with the source 1 - rho~/rho0
  // (less its mean) in place of div u* and dt = 1.
  poisson_->solve(f, s, 1.0, pstar_);
  ++stats_.iterations;
  // Eq. 57: r_a -= grad p*_a / rho0, the gradient in difference form (the halo copies' p* their owners').
  std::vector<double> dx, dy;
  correction_shift(f, domain_.with_halo(pstar_), dx, dy, n);
  for (std::size_t a = 0; a < n; ++a) {
    y[L.pos(0) + a] += dx[a];
    if (L.dim == 2) y[L.pos(1) + a] += dy[a];
  }
}

void DensityCorrection::apply(double t, double* y) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool record = stats_.applications == 0;
  // The r.m.s. fluctuation of rho~/rho0 about its mean (Szewc eq. 56): the kernel's bias on a
  // perfect lattice (Wendland +0.12 % at h = 2 dx) is a constant the correction cannot and need not remove.
  domain_.refresh(t, y);
  std::vector<double> s;
  double error = density_fluctuation(domain_.fields(), domain_.correction_span(), s);
  if (error <= threshold_) return;
  ++stats_.applications;
  if (record) stats_.first_history.push_back(error);
  if (use_newton_) {
    const NewtonCorrectionResult r = correct_density_newton(
        [&](const double* state) { domain_.refresh(t, state); },
        [&]() -> const FluidFields& { return domain_.fields(); }, [&] { return domain_.correction_span(); },
        domain_.layout(), y, max_iterations_, threshold_, spacing_);
    stats_.iterations += r.iterations;
    error = r.error;
  } else if (use_kinsol_) {
    const FluidFields& f = domain_.fields();
    const std::size_t n = domain_.layout().n;
    double volume = 0;  // KINSOL's tolerance on max |F|, F ~ V x relative density fluctuation
    for (std::size_t a = 0; a < n; ++a) volume += f.m[a] / f.rho[a];
    volume /= static_cast<double>(n);
    const KinsolCorrectionResult r = correct_density_kinsol(domain_, t, y, max_iterations_, 0.1 * threshold_ * volume);
    stats_.iterations += r.iterations;
    domain_.refresh(t, y);
    error = density_fluctuation(domain_.fields(), domain_.correction_span(), s);
  } else {
    for (int it = 0; it < max_iterations_ && error > threshold_; ++it) {
      if (it > 0 && record) stats_.first_history.push_back(error);
      fixed_point_step(s, y);
      // The error after the shift decides whether to go on; after the last allowed solve it is
      // only wanted for the recorded history (one right-hand-side evaluation saved per step otherwise).
      if (it + 1 < max_iterations_ || record) {
        domain_.refresh(t, y);
        error = density_fluctuation(domain_.fields(), domain_.correction_span(), s);
      }
    }
  }
  if (record) stats_.first_history.push_back(error);
  stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace arksph
