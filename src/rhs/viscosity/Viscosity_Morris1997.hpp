// Viscosity of Morris et al. 1997, model E of Basa et al. 2008 (eq. 35):
//   (1/rho div tau)_a = sum_b m_b (mu_a + mu_b) / (rho_a rho_b) (r_ab . grad_a W_ab) / r_ab^2 u_ab,
// with mu = rho nu (f.mu). Since grad_a W_ab = F r_ab, (r_ab . grad_a W_ab) / r_ab^2 = F.
// With a kernel correction (Basa §4) grad_a W_ab is replaced by the corrected gradient G_ab, so F
// becomes (r_ab . G_ab) / r_ab^2.
#pragma once
#include "rhs/KernelCorrection_Basa2008.hpp"
#include "rhs/particle_term.hpp"

namespace arksph {

class ViscosityMorris final : public ParticleTerm<ViscosityMorris> {
 public:
  std::string name() const override { return "viscosity:morris"; }
  bool reads_kernel_value() const override { return false; }

  // Particle a's sums: the pair body, then add_to. A term that takes this one over
  // (Term::take_over) runs the same body inside its own pair loop.
  template <class C>
  struct Sums {
    const FluidFields& f;
    std::size_t a;
    double mu_a, inv_rho_a, ua, va;
    bool corrected;
    SplitSum ax, ay;
    Sums(const FluidFields& fields, std::size_t particle)
        : f(fields),
          a(particle),
          mu_a(f.mu[a]),
          inv_rho_a(1.0 / f.rho[a]),
          ua(f.u[a]),
          va(two_d<C>(f) ? f.v[a] : 0.0),
          corrected(!C::plain && f.correction != FluidFields::Correction::none) {}
    // One pair (double) or two (Two) at a time: see split_sum.hpp.
    void operator()(auto lane, auto b, auto rx, auto ry, auto r2, auto w, auto F) {
      if constexpr (!C::plain) {
        if (corrected) {
          double gx, gy;
          corrected_gradient(f, a, rx, ry, w, F, gx, gy);
          F = (rx * gx + ry * gy) / r2;
        }
      }
      const auto mu_sum = mu_a + at(f.mu, b);
      // m_b / (rho_a rho_b) = V_b / rho_a, with 1 / rho_a applied to the sums (one product per
      // particle, not per pair: the pair loop is bound by its multiplications)
      const auto coeff = at(f.vol, b) * mu_sum * F;
      ax[lane] += coeff * (ua - at(f.u, b));
      if (two_d<C>(f)) ay[lane] += coeff * (va - at(f.v, b));
    }
    void add_to(FluidFields& out) const {
      out.dudt[a] += ax.total() * inv_rho_a;
      if (two_d<C>(out)) out.dvdt[a] += ay.total() * inv_rho_a;
    }
  };

  template <class C, class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    Sums<C> sums(f, a);
    nb.for_pairs_split(C{}, sums);
    sums.add_to(f);
  }
};

}  // namespace arksph
