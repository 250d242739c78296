// Viscosity of Cleary, model D of Basa et al. 2008 (eq. 34):
//   (1/rho div tau)_a = sum_b m_b xi / (rho_a rho_b) 4 mu_a mu_b / (mu_a + mu_b)
//                        (u_ab . r_ab) / (r_ab^2 + eta^2) grad_a W_ab,     eta = 0.1 h,
// mu = rho nu, xi calibrated: Cleary's 4.96333 (from Couette flow) gave "highly inaccurate" velocities
// in Basa's Poiseuille runs (Basa §4, after eq. 34), where 4.24 did much better; 4.24 is the default.
// For equal mu and rho the pair weight is 2 xi nu / rho against 8 nu / rho of model C, so xi = 4
// is the value exact for a divergence-free field in 2D. Radial pair forces: conserves momentum.
// With a kernel correction (Basa §4) grad_a W_ab is replaced by the corrected gradient.
#include "kernels/kernel.hpp"
#include "rhs/KernelCorrection_Basa2008.hpp"
#include "rhs/particle_term.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class ViscosityCleary final : public ParticleTerm<ViscosityCleary> {
 public:
  explicit ViscosityCleary(double xi) : xi_(xi) {}
  std::string name() const override { return "viscosity:cleary"; }
  template <class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    const double eta2 = 0.01 * f.kernel->h() * f.kernel->h();
    double ax = 0.0, ay = 0.0;
    const double ua = f.u[a], va = f.dim == 2 ? f.v[a] : 0.0;
    const double mu_a = f.mu[a];
    nb.for_pairs([&](std::uint32_t b, double rx, double ry, double r2, double w, double F) {
      const double mu_b = f.mu[b];
      const double mu_sum = mu_a + mu_b;
      if (mu_sum <= 0) return;
      const double u_dot_r = (ua - f.u[b]) * rx + (f.dim == 2 ? (va - f.v[b]) * ry : 0.0);
      double gx, gy;
      corrected_gradient(f, a, rx, ry, w, F, gx, gy);
      const double coeff =
          f.m[b] * xi_ / (f.rho[a] * f.rho[b]) * 4.0 * mu_a * mu_b / mu_sum * u_dot_r / (r2 + eta2);
      ax += coeff * gx;
      ay += coeff * gy;
    });
    f.dudt[a] += ax;
    if (f.dim == 2) f.dvdt[a] += ay;
  }

 private:
  double xi_;
};

Part<TermFactory> viscosity_cleary() {
  return {"cleary", "model D of Basa et al. 2008 (eq. 34), Cleary's viscosity with calibration constant xi",
          [](const Scene& s) -> std::unique_ptr<Term> {
            return std::make_unique<ViscosityCleary>(part_param<double>(s, "method.cleary_xi"));
          },
          {number("method.cleary_xi", 4.24).in(above(0))
               .doc("model D calibration constant xi (Basa et al. 2008 eq. 34): 4.24 is Basa's calibration on "
                    "Poiseuille flow, where Cleary's 4.96333 (set it to reproduce Cleary) was highly inaccurate; "
                    "4 is exact for a divergence-free 2D field")},
          {.can_be_implicit = true}};
}

}  // namespace arksph
