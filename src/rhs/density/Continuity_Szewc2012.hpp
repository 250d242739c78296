// Continuity equation in the symmetric form of Szewc et al. 2012 eq. 19 (C&R 1999 eq. 3):
//   d rho_a / dt = sum_b m_b (u_a - u_b) . grad_a W_ab,
// with the divergence velocities of the ghosts (free-slip images optional, Szewc §6).
#pragma once
#include "rhs/particle_term.hpp"

namespace arksph {

class ContinuitySzewc final : public ParticleTerm<ContinuitySzewc> {
 public:
  std::string name() const override { return "continuity:szewc19"; }
  bool reads_kernel_value() const override { return false; }

  // Particle a's sum: the pair body, then add_to. A term that takes this one over
  // (Term::take_over) runs the same body inside its own pair loop.
  template <class C>
  struct Sums {
    const FluidFields& f;
    std::size_t a;
    double ua, va;
    SplitSum rate;
    Sums(const FluidFields& fields, std::size_t particle)
        : f(fields), a(particle), ua(f.ud[a]), va(two_d<C>(f) ? f.vd[a] : 0.0) {}
    // One pair (double) or two (Two) at a time: see split_sum.hpp.
    void operator()(auto lane, auto b, auto rx, auto ry, auto, auto, auto F) {
      const auto u_ab = ua - at(f.ud, b);
      const auto v_ab = two_d<C>(f) ? va - at(f.vd, b) : decltype(rx){};
      rate[lane] += at(f.m, b) * F * (u_ab * rx + v_ab * ry);  // m_b u_ab . (F r_ab)
    }
    void add_to(FluidFields& out) const { out.drhodt[a] += rate.total(); }
  };

  template <class C, class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    Sums<C> sums(f, a);
    nb.for_pairs_split(C{}, sums);
    sums.add_to(f);
  }
};

}  // namespace arksph
