// Density by summation, Szewc et al. 2012 eq. 21 (Hu & Adams):  rho_a = m_a sum_b W_ab,
// the sum over all neighbours including ghosts and a itself.
#include "kernels/kernel.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class DensitySummation final : public Term {
 public:
  std::string name() const override { return "density:summation"; }
  Stage stage() const override { return Stage::density; }
  void apply(FluidFields& f) const override {
    const double w_self = f.kernel->W(0.0);
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < f.n_real; ++a) {
      double number_density = w_self;
      f.pairs.for_pairs(a, [&](std::uint32_t, double, double, double, double w, double) { number_density += w; });
      f.rho[a] = f.m[a] * number_density;
    }
  }
};

std::unique_ptr<Term> make_density_summation() { return std::make_unique<DensitySummation>(); }

Part<TermFactory> density_summation() {
  return {"summation", "density by kernel summation over the neighbours (Szewc et al. 2012 eq. 21)",
          [](const Scene&) { return make_density_summation(); }};
}

}  // namespace arksph
