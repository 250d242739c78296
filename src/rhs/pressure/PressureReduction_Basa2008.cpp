// Local pressure reduction of Basa et al. 2008 eq. 20: the pressure-gradient terms use p - p_avg,a,
//   p_avg,a = (1 / N_a) sum_b p_b  over the N_a neighbours of a, a itself included,
// for both p_a and p_b of every pair of particle a. A purely numerical change that lowers the
// F_a / h truncation error of eq. 15; it breaks the a-b symmetry, so momentum is no longer
// conserved exactly (Basa §3). Runs first in the force stage, when ghost pressures are final.
#include "rhs/terms.hpp"

namespace arksph {

class PressureReduction final : public Term {
 public:
  std::string name() const override { return "pressure_reduction:basa20"; }
  Stage stage() const override { return Stage::force; }
  void apply(FluidFields& f) const override {
    f.p_avg.resize(f.n_real);
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < f.n_real; ++a) {
      double sum = f.p[a];
      f.pairs.for_pairs(a, [&](std::uint32_t b, double, double, double, double, double) { sum += f.p[b]; });
      f.p_avg[a] = sum / (1.0 + f.pairs.count[a]);
    }
  }
};

std::unique_ptr<Term> make_pressure_reduction() { return std::make_unique<PressureReduction>(); }

}  // namespace arksph
