// Symmetric pressure gradient of Monaghan, Cummins & Rudman 1999 eq. 1:
//   (1/rho grad p)_a = sum_b m_b (p_a / rho_a^2 + p_b / rho_b^2) grad_a W_ab.
// Antisymmetric in a, b: conserves linear momentum exactly.
#include "rhs/terms.hpp"

namespace arksph {

class PressureGradientMonaghan final : public Term {
 public:
  std::string name() const override { return "pressure_gradient:monaghan"; }
  Stage stage() const override { return Stage::force; }
  void apply(FluidFields& f) const override {
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < f.n_real; ++a) {
      double ax = 0.0, ay = 0.0;
      const double pa_over_rho2 = f.p[a] / (f.rho[a] * f.rho[a]);
      f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
        const double coeff = f.m[b] * (pa_over_rho2 + f.p[b] / (f.rho[b] * f.rho[b])) * F;
        ax -= coeff * rx;
        ay -= coeff * ry;
      });
      f.dudt[a] += ax;
      if (f.dim == 2) f.dvdt[a] += ay;
    }
  }
};

std::unique_ptr<Term> make_pressure_gradient_monaghan() {
  return std::make_unique<PressureGradientMonaghan>();
}

}  // namespace arksph
