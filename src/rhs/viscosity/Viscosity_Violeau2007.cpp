// Viscosity of Violeau & Issa 2007, model C of Basa et al. 2008 (eq. 33):
//   (1/rho div tau)_a = sum_b m_b 8 / (rho_a + rho_b) (mu_a / rho_a + mu_b / rho_b)
//                        (u_ab . r_ab) / (r_ab^2 + eta^2) grad_a W_ab,     eta = 0.1 h,
// with mu / rho = nu. Radial pair forces: conserves linear and angular momentum (uncorrected).
// With a kernel correction (Basa §4) grad_a W_ab is replaced by the corrected gradient.
// The same formula is Szewc et al. 2012 eq. 24 (Cummins & Rudman 1999 eq. 2, after Monaghan; C&R
// write the constant as 4 / xi with xi = 0.24, and 8 is xi = 1/4, exact for a divergence-free 2D
// field): the scene name "monaghan" builds this term under the name viscosity:monaghan.
#include <utility>

#include "kernels/kernel.hpp"
#include "rhs/KernelCorrection_Basa2008.hpp"
#include "rhs/particle_term.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class ViscosityVioleau final : public ParticleTerm<ViscosityVioleau> {
 public:
  explicit ViscosityVioleau(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  template <class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    const double eta2 = 0.01 * f.kernel->h() * f.kernel->h();
    double ax = 0.0, ay = 0.0;
    const double ua = f.u[a], va = f.dim == 2 ? f.v[a] : 0.0;
    nb.for_pairs([&](std::uint32_t b, double rx, double ry, double r2, double w, double F) {
      const double u_dot_r = (ua - f.u[b]) * rx + (f.dim == 2 ? (va - f.v[b]) * ry : 0.0);
      double gx, gy;
      corrected_gradient(f, a, rx, ry, w, F, gx, gy);
      const double nu_sum = 2.0 * f.nu;  // nu_a + nu_b, one fluid
      const double coeff = f.m[b] * 8.0 / (f.rho[a] + f.rho[b]) * nu_sum * u_dot_r / (r2 + eta2);
      ax += coeff * gx;
      ay += coeff * gy;
    });
    f.dudt[a] += ax;
    if (f.dim == 2) f.dvdt[a] += ay;
  }

 private:
  std::string name_;
};

Part<TermFactory> viscosity_violeau() {
  return {"violeau", "model C of Basa et al. 2008 (eq. 33), after Violeau",
          [](const Scene&) -> std::unique_ptr<Term> { return std::make_unique<ViscosityVioleau>("viscosity:violeau"); },
          {}, {.can_be_implicit = true}};
}
Part<TermFactory> viscosity_monaghan() {
  return {"monaghan", "the same pair form as Szewc et al. 2012 eq. 24 and Cummins & Rudman 1999 eq. 2",
          [](const Scene&) -> std::unique_ptr<Term> { return std::make_unique<ViscosityVioleau>("viscosity:monaghan"); },
          {}, {.can_be_implicit = true}};
}

}  // namespace arksph
