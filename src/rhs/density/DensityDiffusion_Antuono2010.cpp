// delta-SPH density diffusion for the continuity equation of WCSPH (Antuono et al. 2010 eq. 4, with
// the diffusive term of Molteni & Colagrossi 2009):
//   drho_a/dt += delta h c sum_b psi_ab . grad_a W_ab V_b,   psi_ab = 2 (rho_b - rho_a) (r_b - r_a) / |r_ab|^2,
// so that, with grad_a W_ab = F r_ab, psi_ab . grad_a W_ab = -2 F (rho_b - rho_a). Under a body force
// g the hydrostatic part of the density difference is left out (Fourtakas et al. 2019, linearised
// equation of state, p_H = rho0 g . r + const): rho_b - rho_a becomes
//   rho_b - rho_a + rho0_a (g . r_ab) / c^2,   r_ab = r_a - r_b,
// so that a fluid at rest in hydrostatic balance has no diffusive flux. Only the components of g
// along axes bounded by walls count (along a periodic axis there is no hydrostatic balance). A wall
// image carries its source's density, so for it r_ab is taken from its source: the image's density
// is the source's hydrostatic one, not that of the image's own depth.
#include "core/errors.hpp"
#include "core/expression.hpp"
#include "core/param_builder.hpp"
#include "rhs/density/density_diffusion_sum.hpp"
#include "rhs/particle_term.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {
namespace {

class DensityDiffusion final : public ParticleTerm<DensityDiffusion>, public DensityDiffusionSum {
 public:
  DensityDiffusion(double delta, double h, double c, double gx, double gy)
      : coeff_(2.0 * delta * h * c), hx_(gx / (c * c)), hy_(gy / (c * c)) {}
  std::string name() const override { return "density_diffusion:delta_sph"; }
  bool reads_kernel_value() const override { return false; }
  std::optional<double> plain_coefficient() const override {
    if (hx_ != 0.0 || hy_ != 0.0) return std::nullopt;
    return coeff_;
  }
  template <class C, class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    const double rho_a = f.rho[a], rho0 = f.rho0[a];
    const double hx = rho0 * hx_, hy = two_d<C>(f) ? rho0 * hy_ : 0.0;
    SplitSum sum;
    if (hx == 0.0 && hy == 0.0) {
      // One pair (double) or two (Two) at a time: see split_sum.hpp.
      nb.for_pairs_split(C{}, [&](auto lane, auto b, auto, auto, auto, auto, auto F) {
        sum[lane] -= F * at(f.vol, b) * (at(f.rho, b) - rho_a);
      });
    } else {
      // A wall image's separation is its source's, looked up per pair: one pair at a time.
      const double xa = f.x[a], ya = f.dim == 2 ? f.y[a] : 0.0;
      nb.for_pairs_split(GeneralPairs{}, [&](auto lane, std::uint32_t b, double rx, double ry, double, double,
                                             double F) {
        if (f.is_wall_image(b)) {
          const std::uint32_t s = f.src[b];
          rx = xa - f.x[s];
          ry = f.dim == 2 ? ya - f.y[s] : 0.0;
        }
        const double dynamic = f.rho[b] - rho_a + (hx * rx + hy * ry);
        sum[lane] -= F * f.vol[b] * dynamic;
      });
    }
    f.drhodt[a] += coeff_ * sum.total();
  }

 private:
  double coeff_;   // 2 delta h c
  double hx_, hy_; // g / c^2 (times rho0 per particle)
};

}  // namespace

std::unique_ptr<Term> make_density_diffusion(const Scene& s, double sound_speed) {
  const double h = s.h_over_dx * s.spacing;
  double g[2] = {0, 0};
  for (int k = 0; k < s.dimension; ++k) {  // a constant body force along a walled axis only
    Expression e(s.body_force.at(k), {"x", "y", "t"});
    const bool walled = s.sides[2 * k].kind == SideKind::wall || s.sides[2 * k + 1].kind == SideKind::wall;
    if (e.is_constant() && walled) g[k] = e.eval(0, 0, 0);
  }
  return std::make_unique<DensityDiffusion>(part_param<double>(s, "method.delta_sph_coefficient"), h, sound_speed,
                                            g[0], g[1]);
}

Part<CompressibleTermsFactory> density_diffusion_none() { return {"none", "no density diffusion"}; }

// The diffusion acts on the continuity equation: refused with a density that is not in the state.
Part<CompressibleTermsFactory> density_diffusion_delta_sph() {
  return {"delta_sph",
          "delta-SPH diffusion in the continuity equation (Antuono et al. 2010 eq. 4, Molteni & Colagrossi 2009), "
          "hydrostatic part left out",
          [](const Scene& scene, double sound_speed) {
            if (!density_modes().at(scene.density_mode).traits.adds_state("density"))
              throw InputError(scene.source + ": method.density_diffusion: \"delta_sph\" needs method.density_mode = \"continuity\" (got \"" +
                               scene.density_mode + "\")");
            std::vector<std::unique_ptr<Term>> terms;
            terms.push_back(make_density_diffusion(scene, sound_speed));
            return terms;
          },
          {number("method.delta_sph_coefficient", 0.1).in(at_least(0))
               .doc("delta of the delta-SPH diffusive term (Antuono et al. 2010: 0.1)")},
          {.schemes = {"wcsph"}}};
}

}  // namespace arksph
