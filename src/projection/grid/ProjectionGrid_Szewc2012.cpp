#include "projection/grid/ProjectionGrid_Szewc2012.hpp"

#include "core/param_builder.hpp"

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

namespace {
// The two deposits' sums combined over the processes: one array of sums and one of maxima (the lows
// negated), so that the combination is two reductions.
void combine_deposits(const CellCombine& combine, DepositSums& a, DepositSums& b) {
  const std::size_t nc = a.value.size();
  std::vector<double> sums, maxima;
  sums.reserve(4 * nc);
  maxima.reserve(4 * nc);
  for (DepositSums* d : {&a, &b}) {
    sums.insert(sums.end(), d->value.begin(), d->value.end());
    sums.insert(sums.end(), d->weight.begin(), d->weight.end());
    for (double lo : d->lo) maxima.push_back(-lo);
    maxima.insert(maxima.end(), d->hi.begin(), d->hi.end());
  }
  combine(sums, maxima);
  std::size_t k = 0;
  for (DepositSums* d : {&a, &b}) {
    for (std::size_t i = 0; i < nc; ++i) d->value[i] = sums[k * nc + i];
    for (std::size_t i = 0; i < nc; ++i) d->weight[i] = sums[(k + 1) * nc + i];
    for (std::size_t i = 0; i < nc; ++i) d->lo[i] = -maxima[k * nc + i];
    for (std::size_t i = 0; i < nc; ++i) d->hi[i] = maxima[(k + 1) * nc + i];
    k += 2;
  }
}
}  // namespace

GridCorrection GridProjection::solve(const FluidFields& f, std::size_t n, const std::vector<double>& divergence,
                                     double dt, const CellCombine& combine) {
  const GridSpec& g = poisson_.grid();
  const double* y = f.dim == 2 ? f.y.data() : nullptr;
  std::vector<double> volume(n), source(n);
  for (std::size_t a = 0; a < n; ++a) {
    volume[a] = f.m[a] / f.rho[a];
    source[a] = divergence[a] / dt;
  }
  DepositSums rho_sums = deposit_sums(g, n, f.x.data(), y, volume.data(), f.rho0.data());
  DepositSums src_sums = deposit_sums(g, n, f.x.data(), y, volume.data(), source.data());
  if (combine) combine_deposits(combine, rho_sums, src_sums);
  const GridDeposit rho = finish_deposit(std::move(rho_sums), fallback_density_);
  const GridDeposit src = finish_deposit(std::move(src_sums), 0.0);
  std::vector<double> rhs = src.value;
  if (volume_relaxation_ > 0) {  // ask for div u = beta (phi - 1)/dt: over-full cells expand
    const double cell = std::pow(g.h, f.dim);
    for (std::size_t i = 0; i < rhs.size(); ++i)
      rhs[i] -= volume_relaxation_ * (src.weight[i] / cell - 1.0) / (dt * dt);
  }
  if (wall_flux_) add_wall_flux(rhs, f.t);
  GridCorrection c;
  c.refactorised = poisson_.set_density(rho.value);
  std::vector<double> p;
  c.residual = poisson_.solve(rhs, p);
  std::vector<double> ax, ay;
  poisson_.acceleration(p, ax, ay);
  c.ax = interpolate(g, n, f.x.data(), y, ax);
  if (f.dim == 2) c.ay = interpolate(g, n, f.x.data(), y, ay);
  c.pressure = interpolate(g, n, f.x.data(), y, p);
  return c;
}

}  // namespace arksph
