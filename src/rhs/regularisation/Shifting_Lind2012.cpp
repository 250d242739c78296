// Fickian particle shifting (Xu, Stansby & Laurence 2009; Lind et al. 2012 eqs. 8-10), written as a
// velocity of the ODE instead of a displacement after each step:
//   dr_a/dt = u_a + du_a,   du_a = -A h U grad C_a,
//   grad C_a = sum_b V0 (1 + R (W_ab / W(dx))^n) grad_a W_ab      (Lind eq. 10, n = 4,
//                                                                   R = method.shifting_anti_clumping),
// with the lattice volume V0 = dx^d of every particle (phases differ in mass, not in number density):
// C measures where the particles are, not the density, so a fluid compressed by its weight (WCSPH
// under gravity) is not shifted.
// with the step-size-free diffusion coefficient D / dt = A h U (Skillen et al. 2013 write D = A h |u| dt;
// U here is the scene's flow speed, the largest initial or wall speed, so that particles near stagnation
// points are shifted too; a fluid that starts at rest between resting walls has U = 0 and no shift).
// Where grad C is large (a lid corner, a particle pushed into a wall) the velocity saturates smoothly
// at s U, du <- du / sqrt(1 + |du|^2 / (s U)^2) with s = method.shifting_limit (Lind et al. 2012 limit
// the displacement per step in the same spirit); on a nearly regular lattice |du| << s U and the
// factor is 1 to second order.
// The carried fields follow the shifted particle, not the fluid (Lind eq. 11 as a rate):
//   du_a/dt += (du_a . grad) u_a,   drho_a/dt += du_a . grad rho_a (WCSPH with the continuity equation),
// with du_a . grad f_a = sum_b V_b (f_b - f_a) du_a . grad_a W_ab. Ghosts count as neighbours, so a
// wall is no free surface: the lattice next to it is not pulled apart.
//
// At a free surface (fluid.region) grad C points into the fluid wherever the surface cuts the
// support, and du would push the particles out through the surface. Lind et al. 2012 (§2.3) shift
// the particles on and near the surface along it only: du = -D (dC/ds s + alpha dC/dn n), alpha = 0.
// Here the particles whose own support is cut (the divergence of position
// div r_a = -sum_b V0 r_ab . grad_a W_ab below kSurfaceBand d; d in a full support) are not shifted
// at all. Along the surface is not a direction at the tip of a surge or a corner of the fluid: with
// the outward part of grad C removed (along n = -g / |g|, g = sum_b V0 grad_a W_ab) and the rest
// kept, the tip particles of a dam break's surge were shifted forwards along the floor and the
// front ran ahead (docs/methods/free-surface.md). A criterion of the particle's own support, so that
// a rank needs no neighbour's flag.
#include <cmath>
#include <limits>
#include <utility>

#include "core/param_builder.hpp"
#include "core/scheme.hpp"
#include "kernels/kernel.hpp"
#include "rhs/density/Continuity_Szewc2012.hpp"
#include "rhs/pressure/PressureGradient_Colagrossi2003.hpp"
#include "rhs/viscosity/Viscosity_Morris1997.hpp"
#include "rhs/density/density_diffusion_sum.hpp"
#include "rhs/particle_term.hpp"
#include "rhs/reference_speed.hpp"
#include "rhs/regularisation/shifting_stability.hpp"
#include "rhs/term_registry.hpp"

namespace arksph {
namespace {

constexpr int kAntiClumpN = 4;  // Lind et al. 2012 eq. 10
// The support counts as cut by a free surface below this fraction of the full divergence of position
// d: the top two rows under a flat surface (div r = 1.18 and 1.63 of 2 in 2D, Wendland quintic with
// h = 2 dx), not the third (1.94), whose small outward push is kept so that a sparse spot inside the
// fluid, where div r dips too, is still filled. docs/methods/free-surface.md has the figures.
constexpr double kSurfaceBand = 0.9;
// Explicit steps keep the linearised shifting stable (rhs/regularisation/shifting_stability.hpp) when rate * dt <= 2:
// the reach along the negative real axis of forward Euler and of the two-stage second-order tables
// (Heun-Euler, the default); the tables of higher order reach further. 0.75 of it leaves room for a
// lattice disordered past the linear analysis.
constexpr double kStableRateStep = 0.75 * 2.0;

class Shifting final : public ParticleTerm<Shifting> {
 public:
  Shifting(double coefficient, double speed, double limit, double h, double w_dx, double v0, double anti_clump,
           bool density, bool free_surface, int dimension)
      : scale_(coefficient * h * speed * v0),
        band_(free_surface && speed > 0 ? kSurfaceBand * dimension / v0 : 0.0),  // U = 0: du = 0 anyway
        anti_clump_(anti_clump),
        inv_limit2_(limit > 0 && speed > 0 ? 1.0 / (limit * speed * limit * speed) : 0.0),  // U = 0: du = 0
        clump_scale_(std::sqrt(std::sqrt(anti_clump)) / w_dx),
        density_(density) {}
  std::string name() const override { return "regularisation:shifting"; }
  bool moves_particles() const override { return true; }
  double max_step() const override { return max_step_; }
  void set_max_step(double dt) { max_step_ = dt; }
  bool reads_kernel_value() const override { return anti_clump_ != 0.0; }
  // delta-SPH without a hydrostatic part sums over the V_b (rho_b - rho_a) that the carried density
  // visits already (rhs/density/density_diffusion_sum.hpp): the evaluator lets this term add it. The pressure
  // gradient, continuity and viscosity of the WCSPH default read the same neighbours, volumes,
  // velocities: taken over, their pair bodies run in the carried fields' loop (all three and delta-SPH,
  // two dimensions, plain pairs), or else their own loops run from here. Either way each adds its sums
  // where the evaluator would have, in the order of terms_from_scene (pressure, continuity, delta-SPH,
  // shifting, viscosity), with the same operations: the same bits as the terms run one by one.
  bool take_over(const Term& other) override {
    if (const auto* p = dynamic_cast<const PressureGradientColagrossi*>(&other); p && !pressure_) {
      pressure_ = p;
      return true;
    }
    if (const auto* c = dynamic_cast<const ContinuitySzewc*>(&other); c && !continuity_) {
      continuity_ = c;
      return true;
    }
    if (const auto* v = dynamic_cast<const ViscosityMorris*>(&other); v && !viscosity_) {
      viscosity_ = v;
      return true;
    }
    const auto* diffusion = dynamic_cast<const DensityDiffusionSum*>(&other);
    if (!diffusion || !density_ || diffuse_) return false;
    const std::optional<double> coeff = diffusion->plain_coefficient();
    if (!coeff) return false;
    diffuse_ = true;
    diffusion_coeff_ = *coeff;
    return true;
  }
  void give_back() override {
    pressure_ = nullptr;
    continuity_ = nullptr;
    viscosity_ = nullptr;
    diffuse_ = false;
  }
  // The pair configuration C (rhs/particle_term.hpp) and whether Lind's weight is on, both fixed
  // outside the pair loop: without it, W_ab is neither gathered nor read.
  template <class C, class Neighbors>
  void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    if constexpr (C::plain) {
      if (pressure_ && continuity_ && viscosity_ && diffuse_) {
        if (anti_clump_ != 0.0)
          sums<C, true, true>(f, a, nb);
        else
          sums<C, false, true>(f, a, nb);
        return;
      }
    }
    if (pressure_) pressure_->template particle<C>(f, a, nb);
    if (continuity_) continuity_->template particle<C>(f, a, nb);
    if (anti_clump_ != 0.0)
      sums<C, true, false>(f, a, nb);
    else
      sums<C, false, false>(f, a, nb);
    if (viscosity_) viscosity_->template particle<C>(f, a, nb);
  }

 private:
  // grad C_a / V0 (V0 is in scale_), summed four ways: pair k adds into lane k % 4, and the total is
  // (s0 + s2) + (s1 + s3). A gathered neighbourhood is walked four pairs at a time (one AVX vector
  // where the build has it); the pair list one pair at a time, with the same lanes, so both give the
  // same bits. Four chains instead of the two of SplitSum: this sum has few operations per pair, and
  // the walk runs at the rate of its loads.
  template <bool kClump>
  std::pair<double, double> grad_c(const Neighborhood& nb) const {
    Quad sx, sy;
    const double *px = nb.rx.data(), *py = nb.ry.data(), *pw = nb.w.data(), *pf = nb.f.data();
    std::size_t k = 0;
    for (; k + 3 < nb.count; k += 4) {
      Four rx, ry, F;
      load_four(px + k, rx);
      load_four(py + k, ry);
      load_four(pf + k, F);
      Four weight = F;
      if constexpr (kClump) {  // clump_weight's operations, four lanes at once
        Four w;
        load_four(pw + k, w);
        const Four q = clump_scale_ * w;
        const Four q2 = q * q;
        weight = (1.0 + q2 * q2) * F;
      }
      sx.s += weight * rx;
      sy.s += weight * ry;
    }
    for (; k < nb.count; ++k) {
      const double weight = clump_weight<kClump>(pw[k], pf[k]);
      sx.s[k & 3] += weight * px[k];
      sy.s[k & 3] += weight * py[k];
    }
    return {sx.total(), sy.total()};
  }
  template <bool kClump>
  std::pair<double, double> grad_c(const PairsOf& nb) const {
    Quad sx, sy;
    std::size_t k = 0;
    nb.for_pairs([&](std::uint32_t, double rx, double ry, double, double w, double F) {
      const double weight = clump_weight<kClump>(w, F);
      sx.s[k & 3] += weight * rx;
      sy.s[k & 3] += weight * ry;
      ++k;
    });
    return {sx.total(), sy.total()};
  }
  // (1 + R (W_ab / W(dx))^n) F_ab with n = 4 (Lind eq. 10), or F_ab without the anti-clumping weight;
  // grad_a W_ab = F_ab r_ab.
  template <bool kClump>
  double clump_weight(double w, double F) const {
    if constexpr (kClump) {
      const double q = clump_scale_ * w;
      const double q2 = q * q;
      return (1.0 + q2 * q2) * F;
    } else {
      return F;
    }
  }

  // Two passes over the neighbours: grad C, then the carried fields weighted by grad C . grad_a W_ab
  // = F (grad C . r_ab), so that they need three sums, not the six of grad u and grad rho. kFused: the
  // taken-over pressure gradient, continuity, delta-SPH and viscosity in the second pass.
  template <class C, bool kClump, bool kFused, class Neighbors>
  void sums(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    const bool two = two_d<C>(f);
    auto [gcx, gcy_any] = grad_c<kClump>(nb);
    double gcy = two ? gcy_any : 0.0;
    if (band_ > 0 && support_cut(nb)) gcx = gcy = 0.0;
    const double ua = f.u[a], va = two ? f.v[a] : 0.0, rho_a = f.rho[a];
    // The carried fields along grad C (du_a is a multiple of it, applied after the sums, so that
    // the pair loop does not wait for the saturation's square root).
    SplitSum du, dv, drho;  // (grad C . grad) u, grad C . grad rho
    SplitSum diffusion;     // delta-SPH's sum, when taken over
    // Fused: two dimensions, the density carried and diffused, known at compile time.
    const bool carry_density = kFused || density_, diffuse = kFused || diffuse_;
    auto carried = [&](auto lane, auto b, auto rx, auto ry, auto, auto, auto F) {
      const auto fv = F * at(f.vol, b);
      const auto along = fv * (gcx * rx + gcy * ry);  // V_b grad C_a . grad_a W_ab
      // x (u_b - u_a) = -(x (u_a - u_b)) exactly: u_a - u_b as the viscosity's (one subtraction when fused)
      du[lane] -= along * (ua - at(f.u, b));
      if (kFused || two) dv[lane] -= along * (va - at(f.v, b));
      if (carry_density) {
        const auto rho_ba = at(f.rho, b) - rho_a;
        drho[lane] += along * rho_ba;
        if (diffuse) diffusion[lane] -= fv * rho_ba;  // as rhs/density/DensityDiffusion_Antuono2010.cpp
      }
    };
    auto add_own = [&] {
      if (diffuse_) f.drhodt[a] += diffusion_coeff_ * diffusion.total();
      double k = -scale_;  // du_a = k grad C_a
      if (inv_limit2_ > 0) k /= std::sqrt(1.0 + k * k * (gcx * gcx + gcy * gcy) * inv_limit2_);
      f.shift_u[a] = k * gcx;
      f.dudt[a] += k * du.total();
      if (two) {
        f.shift_v[a] = k * gcy;
        f.dvdt[a] += k * dv.total();
      }
      if (density_) f.drhodt[a] += k * drho.total();
    };
    if constexpr (kFused) {  // one walk: the loads of b, r_ab, F_ab, V_b, u_b, v_b shared
      PressureGradientColagrossi::Sums<C> pressure(f, a);
      ContinuitySzewc::Sums<C> continuity(f, a);
      ViscosityMorris::Sums<C> viscosity(f, a);
      nb.for_pairs_split(C{}, [&](auto lane, auto b, auto rx, auto ry, auto r2, auto w, auto F) {
        pressure(lane, b, rx, ry, r2, w, F);
        continuity(lane, b, rx, ry, r2, w, F);
        carried(lane, b, rx, ry, r2, w, F);
        viscosity(lane, b, rx, ry, r2, w, F);
      });
      pressure.add_to(f);
      continuity.add_to(f);
      add_own();
      viscosity.add_to(f);
    } else {
      nb.for_pairs_split(C{}, carried);
      add_own();
    }
  }

  // Whether a free surface cuts the particle's support (the header): div r / V0 = -sum_b F_ab r_ab^2
  // below the band, grad_a W_ab = F_ab r_ab.
  template <class Neighbors>
  bool support_cut(const Neighbors& nb) const {
    double div = 0;
    nb.for_pairs([&](std::uint32_t, double, double, double r2, double, double F) { div -= F * r2; });
    return div < band_;
  }

  const PressureGradientColagrossi* pressure_ = nullptr;  // taken over (take_over)
  const ContinuitySzewc* continuity_ = nullptr;
  const ViscosityMorris* viscosity_ = nullptr;
  double scale_;      // A h U V0
  double band_;       // kSurfaceBand d / V0 with a free surface and U > 0, else 0 (no surface treatment)
  double anti_clump_; // R
  double inv_limit2_; // 1 / (s U)^2, 0 without a limit
  double clump_scale_; // R^(1/4) / W(dx): R (W / W(dx))^4 = ((clump_scale_ W)^2)^2
  double max_step_ = std::numeric_limits<double>::infinity();  // set_max_step
  bool density_;      // the density is a state (continuity equation): carried too
  bool diffuse_ = false;        // delta-SPH taken over (take_over)
  double diffusion_coeff_ = 0;  // its 2 delta h c
};

static_assert(kAntiClumpN == 4, "the anti-clumping factor is written out for n = 4");

}  // namespace

Part<TermFactory> regularisation_shifting() {
  return {"shifting",
          "Fickian particle shifting as a velocity in dr/dt (Lind et al. 2012 eqs. 8-11), carried fields corrected",
          [](const Scene& s) -> std::unique_ptr<Term> {
            const double h = s.h_over_dx * s.spacing;
            const Kernel kernel = make_kernel(s.kernel, h, s.dimension);
            double speed = part_param<double>(s, "method.shifting_speed");
            if (speed <= 0) speed = flow_speed(s);
            const bool density = scheme_traits(s.scheme).weakly_compressible &&
                                 density_modes().at(s.density_mode).traits.adds_state("density");
            const double coefficient = part_param<double>(s, "method.shifting_coefficient");
            const double anti_clump = part_param<double>(s, "method.shifting_anti_clumping");
            auto term = std::make_unique<Shifting>(coefficient, speed, part_param<double>(s, "method.shifting_limit"),
                                                   h, kernel.W(s.spacing), std::pow(s.spacing, s.dimension),
                                                   anti_clump, density, !s.fluid_region.empty(), s.dimension);
            const double rate = coefficient * speed / h * shifting_stiffness(kernel, s.spacing, anti_clump);
            if (rate > 0) term->set_max_step(kStableRateStep / rate);
            return term;
          },
          {number("method.shifting_coefficient", 12.0).in(at_least(0))
               .doc("A of the shifting velocity du = -A h U grad C (Lind et al. 2012 eq. 8 with D = A h U dt)"),
           number("method.shifting_anti_clumping", 0.2).in(at_least(0))
               .doc("R of Lind et al. 2012 eq. 10: near neighbours weigh 1 + R (W/W(dx))^4 in grad C (0: plain grad C, no kernel values needed)"),
           number("method.shifting_limit", 0.2).in(at_least(0))
               .doc("s: the shifting velocity saturates smoothly at s U (0: no limit)"),
           number("method.shifting_speed", 0.0).in(at_least(0)).unit("m/s")
               .doc("U of the shifting velocity (0: the flow speed, the largest initial or wall speed)")}};
}

}  // namespace arksph
