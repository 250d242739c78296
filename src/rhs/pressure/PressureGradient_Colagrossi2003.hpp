// Pressure gradient of Colagrossi & Landrini, Szewc et al. 2012 eq. 23:
//   (1/rho grad p)_a = sum_b m_b (p_a + p_b) / (rho_a rho_b) grad_a W_ab.
// Antisymmetric in a, b: conserves linear momentum exactly. With pressure reduction (Basa et al.
// 2008 eq. 20) p_a and p_b become p - p_avg,a; with a kernel correction (Basa §4) grad_a W_ab
// becomes the corrected gradient. Either breaks the exact conservation.
#pragma once
#include "rhs/KernelCorrection_Basa2008.hpp"
#include "rhs/particle_term.hpp"

namespace arksph {

class PressureGradientColagrossi final : public ParticleTerm<PressureGradientColagrossi> {
 public:
  std::string name() const override { return "pressure_gradient:colagrossi"; }
  bool reads_kernel_value() const override { return false; }

  // Particle a's sums: the pair body, then add_to. A term that takes this one over
  // (Term::take_over) runs the same body inside its own pair loop.
  template <class C>
  struct Sums {
    const FluidFields& f;
    std::size_t a;
    double p_ref, pa, inv_rhoa;
    SplitSum ax, ay;
    Sums(const FluidFields& fields, std::size_t particle)
        : f(fields),
          a(particle),
          p_ref(C::plain || f.p_avg.empty() ? 0.0 : f.p_avg[a]),
          pa(f.p[a] - p_ref),
          inv_rhoa(1.0 / f.rho[a]) {}
    // m_b / (rho_a rho_b) = V_b / rho_a; 1 / rho_a is applied to the sums (one product per
    // particle, not per pair: the pair loop is bound by its multiplications).
    void operator()(auto lane, auto b, auto rx, auto ry, auto, auto w, auto F) {
      auto gx = F * rx, gy = F * ry;  // grad_a W_ab; one pair (double) or two (Two): split_sum.hpp
      if constexpr (!C::plain) corrected_gradient(f, a, rx, ry, w, F, gx, gy);
      // without pressure reduction p_ref = 0, and x - 0 = x
      const auto p_sum = C::plain ? pa + at(f.p, b) : pa + at(f.p, b) - p_ref;
      const auto coeff = at(f.vol, b) * p_sum;
      ax[lane] -= coeff * gx;
      ay[lane] -= coeff * gy;
    }
    void add_to(FluidFields& out) const {
      out.dudt[a] += ax.total() * inv_rhoa;
      if (two_d<C>(out)) out.dvdt[a] += ay.total() * inv_rhoa;
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
