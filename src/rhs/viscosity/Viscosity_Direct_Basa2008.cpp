// Direct second derivatives, model A of Basa et al. 2008 (eqs. 6, 27, 28):
//   (1/rho div tau) = nu/3 (4 u_xx + 3 u_yy + v_xy,  3 v_xx + 4 v_yy + u_xy)   (eq. 6, 2D; nu u_xx in 1D)
//   <d2F/dxi dxj>_a = sum_b V_b F_b d2W_ab/dxi dxj                            (eq. 27, self included)
//   d2W/dxi dxj = xi xj / r^2 (W'' - W'/r) + delta_ij W'/r                     (eq. 28; delta_ij W''(0) at r = 0)
// With the Shepard correction the second derivatives take the zero-order form of eq. 23 (built
// from the sums <F>, <dF>, <d2F> and the same sums of the unit field). Basa define no first-order
// second derivative, so bonet_lok uses eq. 23 as well. Not symmetric in a, b: momentum is not
// conserved exactly.
#include <cmath>

#include "kernels/kernel.hpp"
#include "rhs/particle_term.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class ViscosityDirect final : public ParticleTerm<ViscosityDirect> {
 public:
  std::string name() const override { return "viscosity:direct"; }
  template <class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    const double w0 = f.kernel->W(0.0), d2w0 = f.kernel->d2Wdr2(0.0);
    const bool shepard = f.correction != FluidFields::Correction::none;
    const bool two_d = f.dim == 2;
    // Sums for the fields 1, u, v: value S0, gradient S1[2], Hessian S2[xx, xy, yy].
    struct Sums {
      double s0 = 0, s1[2] = {0, 0}, s2[3] = {0, 0, 0};
      void add(double c, double w, double gx, double gy, const double hxx, double hxy, double hyy) {
        s0 += c * w;
        s1[0] += c * gx;
        s1[1] += c * gy;
        s2[0] += c * hxx;
        s2[1] += c * hxy;
        s2[2] += c * hyy;
      }
    } one, su, sv;
    const double va_vol = f.m[a] / f.rho[a];
    const double ua = f.u[a], vva = two_d ? f.v[a] : 0.0;
    one.add(va_vol, w0, 0, 0, d2w0, 0, d2w0);
    su.add(va_vol * ua, w0, 0, 0, d2w0, 0, d2w0);
    sv.add(va_vol * vva, w0, 0, 0, d2w0, 0, d2w0);
    nb.for_pairs([&](std::uint32_t b, double rx, double ry, double r2, double w, double F) {
      const double vb = f.m[b] / f.rho[b];
      const double r = std::sqrt(r2);
      const double d2 = f.kernel->d2Wdr2(r);
      const double k = (d2 - F) / r2;  // (W'' - W'/r) / r^2, with F = W'/r
      const double hxx = rx * rx * k + F, hxy = rx * ry * k, hyy = ry * ry * k + F;
      const double gx = F * rx, gy = F * ry;
      one.add(vb, w, gx, gy, hxx, hxy, hyy);
      su.add(vb * f.u[b], w, gx, gy, hxx, hxy, hyy);
      if (two_d) sv.add(vb * f.v[b], w, gx, gy, hxx, hxy, hyy);
    });
    // Second derivative (i, j) of the field with sums s: eq. 27, or eq. 23 with Shepard.
    auto second = [&](const Sums& s, int i, int j) {
      const int ij = i + j;  // xx -> 0, xy -> 1, yy -> 2
      if (!shepard) return s.s2[ij];
      const double o = one.s0;
      return (s.s2[ij] * o - s.s1[j] * one.s1[i] - s.s1[i] * one.s1[j] - s.s0 * one.s2[ij]) / (o * o) +
             2.0 * s.s0 * one.s1[i] * one.s1[j] / (o * o * o);
    };
    const double nu = f.nu;
    if (!two_d) {
      f.dudt[a] += nu * second(su, 0, 0);
      return;
    }
    const double uxx = second(su, 0, 0), uyy = second(su, 1, 1), uxy = second(su, 0, 1);
    const double vxx = second(sv, 0, 0), vyy = second(sv, 1, 1), vxy = second(sv, 0, 1);
    f.dudt[a] += nu / 3.0 * (4.0 * uxx + 3.0 * uyy + vxy);
    f.dvdt[a] += nu / 3.0 * (3.0 * vxx + 4.0 * vyy + uxy);
  }
};

Part<TermFactory> viscosity_direct() {
  return {"direct", "model A of Basa et al. 2008 (eqs. 27-28): direct second derivatives of the kernel",
          [](const Scene&) -> std::unique_ptr<Term> { return std::make_unique<ViscosityDirect>(); }, {},
          {.can_be_implicit = true}};
}

}  // namespace arksph
