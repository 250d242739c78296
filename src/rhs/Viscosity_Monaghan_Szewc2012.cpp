// Viscosity in the form of Szewc et al. 2012 eq. 24 (Cummins & Rudman 1999 eq. 2, after Monaghan):
//   (nu lap u)_a = sum_b m_b 8 (nu_a + nu_b) / (rho_a + rho_b) (u_ab . r_ab) / (r_ab^2 + eta^2) grad_a W_ab,
// eta^2 = 0.01 h^2. C&R write the constant as 4 / xi with a calibration xi = 0.24; 8 corresponds to
// xi = 1/4 for equal viscosities, the value exact for a divergence-free field in 2D.
#include "kernels/kernel.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class ViscosityMonaghan final : public Term {
 public:
  std::string name() const override { return "viscosity:monaghan"; }
  Stage stage() const override { return Stage::force; }
  void apply(FluidFields& f) const override {
    const double eta2 = 0.01 * f.kernel->h() * f.kernel->h();
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < f.n_real; ++a) {
      double ax = 0.0, ay = 0.0;
      const double ua = f.u[a], va = f.dim == 2 ? f.v[a] : 0.0;
      f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double r2, double, double F) {
        const double u_dot_r = (ua - f.u[b]) * rx + (f.dim == 2 ? (va - f.v[b]) * ry : 0.0);
        const double coeff =
            f.m[b] * 8.0 * (f.nu[a] + f.nu[b]) / (f.rho[a] + f.rho[b]) * u_dot_r / (r2 + eta2) * F;
        ax += coeff * rx;
        ay += coeff * ry;
      });
      f.dudt[a] += ax;
      if (f.dim == 2) f.dvdt[a] += ay;
    }
  }
};

std::unique_ptr<Term> make_viscosity_monaghan() { return std::make_unique<ViscosityMonaghan>(); }

}  // namespace arksph
