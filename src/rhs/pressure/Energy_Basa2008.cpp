// Energy equation in symmetrised form, Basa et al. 2008 eq. 14 (viscous heating neglected, Basa §2.1.4):
//   de_a/dt = 1/2 sum_b m_b (p_a / rho_a^2 + p_b / rho_b^2) (u_a - u_b) . grad_a W_ab.
// Used with the ideal-gas equation of state only; the kernel gradient is the one the pressure term
// uses (corrected when a kernel correction is on).
#include "rhs/KernelCorrection_Basa2008.hpp"
#include "rhs/particle_term.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class EnergyEquation final : public ParticleTerm<EnergyEquation> {
 public:
  std::string name() const override { return "energy:basa14"; }
  template <class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    const double pa = f.p[a] / (f.rho[a] * f.rho[a]);
    const double ua = f.ud[a], va = f.dim == 2 ? f.vd[a] : 0.0;
    double rate = 0.0;
    nb.for_pairs([&](std::uint32_t b, double rx, double ry, double, double w, double F) {
      double gx, gy;
      corrected_gradient(f, a, rx, ry, w, F, gx, gy);
      const double dot = (ua - f.ud[b]) * gx + (f.dim == 2 ? (va - f.vd[b]) * gy : 0.0);
      rate += f.m[b] * (pa + f.p[b] / (f.rho[b] * f.rho[b])) * dot;
    });
    f.dedt[a] += 0.5 * rate;
  }
};

std::unique_ptr<Term> make_energy_equation() { return std::make_unique<EnergyEquation>(); }

}  // namespace arksph
