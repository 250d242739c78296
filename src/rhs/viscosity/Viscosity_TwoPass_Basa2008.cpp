// Two-pass (nested first derivative) viscosity, model B of Basa et al. 2008 (eqs. 4, 5, 29):
//   pass 1, at every point b that a real particle sees: D_b = <grad u>_b = sum_c V_c u_c (x) grad_b W_bc,
//           stress tau_b = mu (D + D^T) - lambda (tr D) I, lambda = 2/3 mu      (eq. 4),
//   pass 2: (1/rho div tau)_a = sum_b m_b (tau_a / rho_a^2 + tau_b / rho_b^2) . grad_a W_ab,
// the outer derivative in the symmetric form of Basa eq. 8 with sigma = tau, so that (uncorrected)
// pair forces are opposite and linear momentum is conserved. With a kernel correction (Basa §4)
// both passes use the corrected gradient, in the difference form sum_c V_c (u_c - u_b) G_bc.
//
// A ghost b at depth d behind a wall needs neighbours down to d + R: the term asks for ghost layers
// twice as deep (needs_ghost_velocity_gradients; boundary/ghosts.hpp ghost_depth, Basa §5.2).
// Reflected ghosts get their own first pass over the points within R (a cell search); periodic
// images copy their source's stress.
//
// The SPH gradient of a row sawtooth u = (-1)^j on a lattice is zero (grad W is odd), so the nested
// form does not damp it. Mirrored wall velocities continue the sawtooth into the ghosts, so the
// walls do not damp it either: with boundary.wall_velocity = "mirror" the even and odd rows next to
// a wall drift apart on a start-up (tests/physics/test_two_pass_ghosts.cpp); the extrapolating
// rules (linear, quadratic; Basa §6.1.2) tie the ghosts to the first row and avoid it.
#include <cmath>

#include "kernels/kernel.hpp"
#include "neighbors/cell_list.hpp"
#include "rhs/KernelCorrection_Basa2008.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class ViscosityTwoPass final : public Term {
 public:
  std::string name() const override { return "viscosity:two_pass"; }
  Stage stage() const override { return Stage::force; }
  void apply(FluidFields& f) const override {
    const std::size_t n = f.n_real, n_all = f.n_all;
    const bool two_d = f.dim == 2;
    for (auto* d : {&dux_, &duy_, &dvx_, &dvy_}) d->assign(n_all, 0.0);
    const bool corrected = f.correction != FluidFields::Correction::none;
    // Adds the pair (i, j) to the velocity gradient of point i.
    auto accumulate = [&](std::size_t i, std::size_t j, double rx, double ry, double w, double F, double* g) {
      const double vj = f.m[j] / f.rho[j];
      double gx, gy;
      corrected_gradient(f, i, rx, ry, w, F, gx, gy);
      const double du = corrected ? f.u[j] - f.u[i] : f.u[j];
      const double dv = two_d ? (corrected ? f.v[j] - f.v[i] : f.v[j]) : 0.0;
      g[0] += vj * du * gx, g[1] += vj * du * gy, g[2] += vj * dv * gx, g[3] += vj * dv * gy;
    };
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      double g[4] = {0, 0, 0, 0};
      f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double w, double F) {
        accumulate(a, b, rx, ry, w, F, g);
      });
      dux_[a] = g[0], duy_[a] = g[1], dvx_[a] = g[2], dvy_[a] = g[3];
    }
    bool any_reflected = false;
    for (std::size_t i = n; i < n_all; ++i) any_reflected |= is_reflected(f, i);
    if (any_reflected) cells_.build(f.x.data(), two_d ? f.y.data() : nullptr, n_all, f.kernel->radius());
    const double r_max2 = f.kernel->radius() * f.kernel->radius();
#pragma omp parallel for schedule(static)
    for (std::size_t i = n; i < n_all; ++i) {
      const std::size_t s = f.src[i];
      if (!is_reflected(f, i)) {  // periodic image: same neighbourhood as its source
        dux_[i] = dux_[s], duy_[i] = duy_[s], dvx_[i] = dvx_[s], dvy_[i] = dvy_[s];
        continue;
      }
      double g[4] = {0, 0, 0, 0};
      cells_.for_each_near(f.x[i], two_d ? f.y[i] : 0.0, [&](std::uint32_t j, double dx, double dy) {
        const double r2 = dx * dx + dy * dy;
        if (j == i || r2 >= r_max2) return;
        double w, F;
        f.kernel->eval(std::sqrt(r2), w, F);
        accumulate(i, j, dx, dy, w, F, g);
      });
      dux_[i] = g[0], duy_[i] = g[1], dvx_[i] = g[2], dvy_[i] = g[3];
    }
    // Stress over rho^2 at every point (eq. 4).
    txx_.resize(n_all), txy_.resize(n_all), tyy_.resize(n_all);
    for (std::size_t i = 0; i < n_all; ++i) {
      const double mu = f.rho[i] * f.nu, lambda = 2.0 / 3.0 * mu, div = dux_[i] + dvy_[i];
      const double s = 1.0 / (f.rho[i] * f.rho[i]);
      txx_[i] = s * (2.0 * mu * dux_[i] - lambda * div);
      txy_[i] = s * mu * (duy_[i] + dvx_[i]);
      tyy_[i] = s * (2.0 * mu * dvy_[i] - lambda * div);
    }
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      double ax = 0.0, ay = 0.0;
      f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double w, double F) {
        double gx, gy;
        corrected_gradient(f, a, rx, ry, w, F, gx, gy);
        const double sxx = txx_[a] + txx_[b], sxy = txy_[a] + txy_[b], syy = tyy_[a] + tyy_[b];
        ax += f.m[b] * (sxx * gx + sxy * gy);
        ay += f.m[b] * (sxy * gx + syy * gy);
      });
      f.dudt[a] += ax;
      if (two_d) f.dvdt[a] += ay;
    }
  }

 private:
  static bool is_reflected(const FluidFields& f, std::size_t i) { return f.is_wall_image(i); }
  mutable CellList cells_;
  mutable std::vector<double> dux_, duy_, dvx_, dvy_, txx_, txy_, tyy_;
};

Part<TermFactory> viscosity_two_pass() {
  return {"two_pass", "model B of Basa et al. 2008 (eq. 29): SPH divergence of the SPH velocity gradient",
          [](const Scene&) -> std::unique_ptr<Term> { return std::make_unique<ViscosityTwoPass>(); }, {},
          {.stencil_depth = 2, .can_be_implicit = true}};
}

}  // namespace arksph
