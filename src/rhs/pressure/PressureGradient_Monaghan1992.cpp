// Symmetric pressure gradient of Monaghan, Cummins & Rudman 1999 eq. 1:
//   (1/rho grad p)_a = sum_b m_b (p_a / rho_a^2 + p_b / rho_b^2) grad_a W_ab.
// Antisymmetric in a, b: conserves linear momentum exactly. With pressure reduction (Basa et al.
// 2008 eq. 20) p_a and p_b become p - p_avg,a; with a kernel correction (Basa §4) grad_a W_ab
// becomes the corrected gradient. Either breaks the exact conservation.
#include "rhs/KernelCorrection_Basa2008.hpp"
#include "rhs/particle_term.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class PressureGradientMonaghan final : public ParticleTerm<PressureGradientMonaghan> {
 public:
  std::string name() const override { return "pressure_gradient:monaghan"; }
  template <class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    double ax = 0.0, ay = 0.0;
    const double p_ref = f.p_avg.empty() ? 0.0 : f.p_avg[a];
    const double pa_over_rho2 = (f.p[a] - p_ref) / (f.rho[a] * f.rho[a]);
    nb.for_pairs([&](std::uint32_t b, double rx, double ry, double, double w, double F) {
      double gx, gy;
      corrected_gradient(f, a, rx, ry, w, F, gx, gy);
      const double coeff = f.m[b] * (pa_over_rho2 + (f.p[b] - p_ref) / (f.rho[b] * f.rho[b]));
      ax -= coeff * gx;
      ay -= coeff * gy;
    });
    f.dudt[a] += ax;
    if (f.dim == 2) f.dvdt[a] += ay;
  }
};

Part<TermFactory> pressure_gradient_monaghan() {
  return {"monaghan", "(p_a / rho_a^2 + p_b / rho_b^2) form of Monaghan 1992 (Cummins & Rudman 1999 eq. 1)",
          [](const Scene&) -> std::unique_ptr<Term> { return std::make_unique<PressureGradientMonaghan>(); }};
}

}  // namespace arksph
