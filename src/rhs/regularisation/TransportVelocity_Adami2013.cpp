// Transport velocity of Adami, Hu & Adams 2013, as a velocity of the ODE: the particles move with
// the transport velocity u~ = u + du (eq. 13 integrated over one step is du = -(dt p_b / rho_a)
// sum_b (V_a^2 + V_b^2)/V_a grad_a W_ab with the background pressure p_b; here the step-size-free
// coefficient dt p_b / rho = A h U with the flow speed U, scaled as the shifting velocity so that A means
// the same):
//   du_a = -A h U sum_b (V_a^2 + V_b^2) / (2 V_a) grad_a W_ab,
// and the momentum equation gains the divergence of the extra stress A = rho u (u~ - u) (eq. 8):
//   du_a/dt += 1/m_a sum_b (V_a^2 + V_b^2) (A_a + A_b)/2 . grad_a W_ab,   (A . g)_i = rho u_i (du . g).
// Ghosts take their source's du, reflected like a velocity where they are wall images. With the
// continuity equation the density is carried along u~ as well: drho_a/dt += du_a . grad rho_a.
#include "core/param_builder.hpp"
#include "core/scheme.hpp"
#include "rhs/reference_speed.hpp"
#include "rhs/term_registry.hpp"

namespace arksph {
namespace {

class TransportVelocity final : public Term {
 public:
  TransportVelocity(double scale, bool density) : scale_(scale), density_(density) {}
  std::string name() const override { return "regularisation:transport_velocity"; }
  Stage stage() const override { return Stage::force; }
  bool moves_particles() const override { return true; }
  void apply(FluidFields& f) const override {
    const std::size_t n = f.n_real, n_all = f.n_all;
    const bool two_d = f.dim == 2;
    f.shift_u.resize(n_all);
    if (two_d) f.shift_v.resize(n_all);
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      const double va = f.vol[a];
      double sx = 0, sy = 0;
      f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
        const double vb = f.vol[b];
        const double c = (va * va + vb * vb) / (2.0 * va) * F;
        sx += c * rx;
        sy += c * ry;
      });
      f.shift_u[a] = -scale_ * sx;
      if (two_d) f.shift_v[a] = -scale_ * sy;
    }
    for (std::size_t i = n; i < n_all; ++i) {  // ghosts: the source's du, reflected at walls
      const std::size_t s = f.src[i];
      f.shift_u[i] = f.flip_x[i] * f.shift_u[s];
      if (two_d) f.shift_v[i] = f.flip_y[i] * f.shift_v[s];
    }
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      const double va = f.vol[a];
      const double sa_x = f.shift_u[a], sa_y = two_d ? f.shift_v[a] : 0.0;
      const double rho_a = f.rho[a], ua = f.u[a], v_a = two_d ? f.v[a] : 0.0;
      double ax = 0, ay = 0, grx = 0, gry = 0;
      f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
        const double vb = f.vol[b];
        const double gx = F * rx, gy = F * ry;
        const double sb_x = f.shift_u[b], sb_y = two_d ? f.shift_v[b] : 0.0;
        const double da = rho_a * (sa_x * gx + sa_y * gy);     // rho_a (du_a . g)
        const double db = f.rho[b] * (sb_x * gx + sb_y * gy);  // rho_b (du_b . g)
        const double c = 0.5 * (va * va + vb * vb);
        ax += c * (ua * da + f.u[b] * db);
        if (two_d) ay += c * (v_a * da + f.v[b] * db);
        if (density_) {
          const double dr = vb * (f.rho[b] - rho_a);
          grx += dr * gx;
          gry += dr * gy;
        }
      });
      const double inv_m = 1.0 / f.m[a];
      f.dudt[a] += ax * inv_m;
      if (two_d) f.dvdt[a] += ay * inv_m;
      if (density_) f.drhodt[a] += sa_x * grx + sa_y * gry;
    }
  }

 private:
  double scale_;  // A h U
  bool density_;
};

}  // namespace

Part<TermFactory> regularisation_transport_velocity() {
  return {"transport_velocity",
          "transport velocity with background pressure and the extra stress term (Adami, Hu & Adams 2013 eqs. 8, 13)",
          [](const Scene& s) -> std::unique_ptr<Term> {
            const double h = s.h_over_dx * s.spacing;
            double speed = part_param<double>(s, "method.transport_speed");
            if (speed <= 0) speed = flow_speed(s);
            const bool density = scheme_traits(s.scheme).weakly_compressible &&
                                 density_modes().at(s.density_mode).traits.adds_state("density");
            return std::make_unique<TransportVelocity>(part_param<double>(s, "method.transport_coefficient") * h * speed,
                                                       density);
          },
          {number("method.transport_coefficient", 2.0).in(at_least(0))
               .doc("A of the background-pressure velocity du = -A h U sum_b (V_a^2 + V_b^2)/(2 V_a) grad W "
                    "(Adami et al. 2013 eq. 13 with dt p_b / rho = A h U)"),
           number("method.transport_speed", 0.0).in(at_least(0)).unit("m/s")
               .doc("U of the transport velocity (0: the flow speed, the largest initial or wall speed)")},
          {.quadratic_walls = true}};
}

}  // namespace arksph
