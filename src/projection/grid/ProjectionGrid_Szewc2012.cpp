#include "projection/grid/ProjectionGrid_Szewc2012.hpp"

#include "core/param_builder.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/errors.hpp"
#include "projection/grid/grid_transfer.hpp"
#include "rhs/pressure_gravity.hpp"

namespace arksph {

const std::vector<Param>& grid_projection_params() {
  static const std::vector<Param> params = {
      number("method.gpps_spacing", 0.0).in(at_least(0)).unit("m").schemes({"isph-gpps"})
          .doc("cell size of the auxiliary Poisson grid (Szewc et al. 2012 §4.2); 0: fluid.spacing; must divide the box")
          .to(&Scene::gpps_spacing),
      number("method.gpps_volume_relaxation", 0.0).in(between(0, 1))
          .doc("beta of the source term -beta (phi - 1) / dt^2, phi = particle volume per cell / cell volume (0: off)")
          .to(&Scene::gpps_volume_relaxation),
  };
  return params;
}

GridSpec gpps_grid(const Scene& scene) {
  GridSpec g;
  g.h = scene.gpps_spacing > 0 ? scene.gpps_spacing : scene.spacing;
  g.x0 = scene.min[0];
  g.y0 = scene.dimension == 2 ? scene.min[1] : 0.0;
  int count[2] = {1, 1};
  for (int k = 0; k < scene.dimension; ++k) {
    const double cells = (scene.max[k] - scene.min[k]) / g.h;
    count[k] = static_cast<int>(std::lround(cells));
    if (count[k] < 2 || std::abs(cells - count[k]) > 1e-6 * cells)
      throw InputError(scene.source + ": method.gpps_spacing: " + std::to_string(g.h) +
                       " must divide the box length into at least 2 cells");
    g.periodic[k] = scene.sides[2 * k].kind == SideKind::periodic;
  }
  g.nx = count[0];
  g.ny = count[1];
  return g;
}

GridProjection::GridProjection(const Scene& scene)
    : poisson_(gpps_grid(scene)),
      fallback_density_(scene.density),
      volume_relaxation_(scene.gpps_volume_relaxation),
      force_(momentum_body_force(scene), scene.dimension) {
  bool walls = false;
  for (int s = 0; s < 2 * scene.dimension; ++s) walls = walls || scene.sides[s].kind == SideKind::wall;
  wall_flux_ = walls && !force_.zero();
}

void GridProjection::add_wall_flux(std::vector<double>& rhs, double t) const {
  const GridSpec& g = poisson_.grid();
  const bool two_d = g.ny > 1;
  double acc[2];
  // Along x: the faces x = x0 and x = x0 + nx h of every row (outer normals -x and +x).
  if (!g.periodic[0])
    for (int j = 0; j < g.ny; ++j) {
      const double yc = g.y0 + (j + 0.5) * g.h;
      force_.at(g.x0, yc, t, acc);
      rhs[g.index(0, j)] -= -acc[0] / g.h;
      force_.at(g.x0 + g.nx * g.h, yc, t, acc);
      rhs[g.index(g.nx - 1, j)] -= acc[0] / g.h;
    }
  if (two_d && !g.periodic[1])
    for (int i = 0; i < g.nx; ++i) {
      const double xc = g.x0 + (i + 0.5) * g.h;
      force_.at(xc, g.y0, t, acc);
      rhs[g.index(i, 0)] -= -acc[1] / g.h;
      force_.at(xc, g.y0 + g.ny * g.h, t, acc);
      rhs[g.index(i, g.ny - 1)] -= acc[1] / g.h;
    }
}

GridCorrection GridProjection::solve(const FluidFields& f, std::size_t n, const std::vector<double>& divergence,
                                     double dt, const CellCombine& combine) {
  const GridSpec& g = poisson_.grid();
  const std::size_t nc = g.cells();
  const double* y = f.dim == 2 ? f.y.data() : nullptr;
  std::vector<double> volume(n), source(n);
  double rho_lo = HUGE_VAL, rho_hi = -HUGE_VAL;
  for (std::size_t a = 0; a < n; ++a) {
    volume[a] = f.m[a] / f.rho[a];
    source[a] = divergence[a] / dt;
    rho_lo = std::min(rho_lo, f.rho0[a]);
    rho_hi = std::max(rho_hi, f.rho0[a]);
  }
  if (combine) {
    std::vector<double> none, extremes{-rho_lo, rho_hi};
    combine(none, extremes);
    rho_lo = -extremes[0];
    rho_hi = extremes[1];
  }
  // One phase (every particle's rho0 the fallback density): the deposit of rho0 is the fallback in
  // every cell, bit for bit (the contributing particles all carry it, the empty cells take it), and
  // is not made. The source deposit and its weights are the only arrays combined over the ranks.
  const bool one_density = rho_lo == fallback_density_ && rho_hi == fallback_density_;
  DepositSums src_sums = deposit_sums(g, n, f.x.data(), y, volume.data(), source.data(), false);
  GridCorrection c;
  if (one_density) {
    if (combine) {
      std::vector<double> sums(2 * nc), none;
      std::copy(src_sums.value.begin(), src_sums.value.end(), sums.begin());
      std::copy(src_sums.weight.begin(), src_sums.weight.end(), sums.begin() + static_cast<long>(nc));
      combine(sums, none);
      std::copy(sums.begin(), sums.begin() + static_cast<long>(nc), src_sums.value.begin());
      std::copy(sums.begin() + static_cast<long>(nc), sums.end(), src_sums.weight.begin());
    }
    c.refactorised = poisson_.set_density(fallback_density_);
  } else {
    // Several densities: the rho0 deposit with its extremes (a cell whose particles all carry one
    // rho0 gets it exactly). Its weights are the source deposit's (the same particles, volumes and
    // cell weights), so they are combined once.
    DepositSums rho_sums = deposit_sums(g, n, f.x.data(), y, volume.data(), f.rho0.data(), true);
    if (combine) {
      std::vector<double> sums, maxima;
      sums.reserve(3 * nc);
      maxima.reserve(2 * nc);
      sums.insert(sums.end(), rho_sums.value.begin(), rho_sums.value.end());
      sums.insert(sums.end(), src_sums.value.begin(), src_sums.value.end());
      sums.insert(sums.end(), src_sums.weight.begin(), src_sums.weight.end());
      for (double lo : rho_sums.lo) maxima.push_back(-lo);
      maxima.insert(maxima.end(), rho_sums.hi.begin(), rho_sums.hi.end());
      combine(sums, maxima);
      for (std::size_t i = 0; i < nc; ++i) {
        rho_sums.value[i] = sums[i];
        src_sums.value[i] = sums[nc + i];
        src_sums.weight[i] = rho_sums.weight[i] = sums[2 * nc + i];
        rho_sums.lo[i] = -maxima[i];
        rho_sums.hi[i] = maxima[nc + i];
      }
    }
    c.refactorised = poisson_.set_density(finish_deposit(std::move(rho_sums), fallback_density_).value);
  }
  const GridDeposit src = finish_deposit(std::move(src_sums), 0.0);
  std::vector<double> rhs = src.value;
  if (volume_relaxation_ > 0) {  // ask for div u = beta (phi - 1)/dt: over-full cells expand
    const double cell = std::pow(g.h, f.dim);
    for (std::size_t i = 0; i < rhs.size(); ++i)
      rhs[i] -= volume_relaxation_ * (src.weight[i] / cell - 1.0) / (dt * dt);
  }
  if (wall_flux_) add_wall_flux(rhs, f.t);
  std::vector<double> p;
  c.residual = poisson_.solve(rhs, p);
  // (1/rho) grad p only in the cells that this process's particles interpolate from.
  std::vector<double> ax, ay;
  poisson_.acceleration(p, ax, ay, cell_box(g, n, f.x.data(), y));
  std::vector<std::vector<double>> at = f.dim == 2 ? interpolate_fields(g, n, f.x.data(), y, {&ax, &ay, &p})
                                                   : interpolate_fields(g, n, f.x.data(), y, {&ax, &p});
  c.ax = std::move(at.front());
  if (f.dim == 2) c.ay = std::move(at[1]);
  c.pressure = std::move(at.back());
  return c;
}

}  // namespace arksph
