// Continuity equation in the symmetric form of Szewc et al. 2012 eq. 19 (C&R 1999 eq. 3):
//   d rho_a / dt = sum_b m_b (u_a - u_b) . grad_a W_ab,
// with the divergence velocities of the ghosts (free-slip images optional, Szewc §6).
#include "rhs/particle_term.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class ContinuitySzewc final : public ParticleTerm<ContinuitySzewc> {
 public:
  std::string name() const override { return "continuity:szewc19"; }
  bool reads_kernel_value() const override { return false; }
  template <class C, class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    SplitSum rate;
    const double ua = f.ud[a], va = two_d<C>(f) ? f.vd[a] : 0.0;
    // One pair (double) or two (Two) at a time: see split_sum.hpp.
    nb.for_pairs_split(C{}, [&](auto lane, auto b, auto rx, auto ry, auto, auto, auto F) {
      const auto u_ab = ua - at(f.ud, b);
      const auto v_ab = two_d<C>(f) ? va - at(f.vd, b) : decltype(rx){};
      rate[lane] += at(f.m, b) * F * (u_ab * rx + v_ab * ry);  // m_b u_ab . (F r_ab)
    });
    f.drhodt[a] += rate.total();
  }
};

std::unique_ptr<Term> make_continuity() { return std::make_unique<ContinuitySzewc>(); }

Part<TermFactory> density_continuity() {
  return {"continuity", "density from the continuity equation in the ODE state (Szewc et al. 2012 eq. 19)",
          nullptr, {}, {.state = {"density"}}};
}

}  // namespace arksph
