// Pressure gradient of Colagrossi & Landrini, Szewc et al. 2012 eq. 23:
//   (1/rho grad p)_a = sum_b m_b (p_a + p_b) / (rho_a rho_b) grad_a W_ab.
// Antisymmetric in a, b: conserves linear momentum exactly.
#include "rhs/terms.hpp"

namespace arksph {

class PressureGradientColagrossi final : public Term {
 public:
  std::string name() const override { return "pressure_gradient:colagrossi"; }
  Stage stage() const override { return Stage::force; }
  void apply(FluidFields& f) const override {
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < f.n_real; ++a) {
      double ax = 0.0, ay = 0.0;
      const double pa = f.p[a], rhoa = f.rho[a];
      f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
        const double coeff = f.m[b] * (pa + f.p[b]) / (rhoa * f.rho[b]) * F;
        ax -= coeff * rx;
        ay -= coeff * ry;
      });
      f.dudt[a] += ax;
      if (f.dim == 2) f.dvdt[a] += ay;
    }
  }
};

std::unique_ptr<Term> make_pressure_gradient_colagrossi() {
  return std::make_unique<PressureGradientColagrossi>();
}

}  // namespace arksph
