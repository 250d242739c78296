#include "projection/body_force_split.hpp"

#include <algorithm>

#include "rhs/pressure_gravity.hpp"

namespace arksph {

BodyForceSplit::BodyForceSplit(const Scene& scene) : force_(momentum_body_force(scene), scene) {
  bool walls = false;
  for (int s = 0; s < 2 * scene.dimension; ++s) walls = walls || scene.sides[s].kind == SideKind::wall;
  active_ = walls && !force_.zero();
}

void BodyForceSplit::at(std::size_t n, const double* x, const double* y, double t, std::vector<double>& gx,
                        std::vector<double>& gy) const {
  gx.resize(n);
  gy.resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    double g[2];
    force_.walled_at(x[a], y ? y[a] : 0.0, t, g);
    gx[a] = g[0];
    gy[a] = g[1];
  }
}

std::vector<double> BodyForceSplit::divergence(const FluidFields& f) const {
  std::vector<double> div(f.n_real, 0.0);
  if (force_.uniform()) return div;
  std::vector<double> gx, gy;
  at(f.n_all, f.x.data(), f.dim == 2 ? f.y.data() : nullptr, f.t, gx, gy);
  for (std::size_t a = 0; a < f.n_real; ++a) {
    double s = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      s += f.m[b] / f.rho[b] * F * ((gx[b] - gx[a]) * rx + (gy[b] - gy[a]) * ry);
    });
    div[a] = s;  // sum_b V_b (g_b - g_a) . grad_a W_ab: c for g = (c x, 0)
  }
  return div;
}

void BodyForceSplit::remove_step(std::size_t n, const double* x, const double* y, double t, double dt, double* u,
                                 double* v) {
  at(n, x, y, t, gx_, gy_);
  saved_u_.assign(u, u + n);
  if (v) saved_v_.assign(v, v + n);
  for (std::size_t a = 0; a < n; ++a) {
    u[a] -= dt * gx_[a];
    if (v) v[a] -= dt * gy_[a];
  }
}

void BodyForceSplit::restore_velocities(double* u, double* v) const {
  std::copy(saved_u_.begin(), saved_u_.end(), u);
  if (v) std::copy(saved_v_.begin(), saved_v_.end(), v);
}

}  // namespace arksph
