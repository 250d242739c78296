#include "projection/free_surface.hpp"

#include <algorithm>
#include <cmath>

#include "projection/ppe_row.hpp"
#include "projection/velocity_correction.hpp"

namespace arksph {

DirichletRows surface_rows(const FluidFields& f, std::size_t n, double threshold, double depth,
                           const std::vector<RenormalisedGradient>& last) {
  DirichletRows given;
  given.fixed = free_surface_particles(f, threshold);
  given.fixed.resize(n);
  given.value.assign(n, 0.0);
  if (last.empty()) return given;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    if (!given.fixed[a]) continue;
    const RenormalisedGradient& g = last[a];
    if (!g.regular) continue;
    double cx = 0, cy = 0;  // sum_b V_b grad_a W_ab: into the fluid
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double vb = f.m[b] / f.rho[b];
      cx += vb * F * rx;
      cy += vb * F * ry;
    });
    const double norm = std::hypot(cx, cy);
    if (!(norm > 0)) continue;
    given.value[a] = std::max(0.0, depth * (g.x * cx + g.y * cy) / norm);
  }
  return given;
}

std::vector<double> linear_laplacian_defect(const FluidFields& f, const std::vector<RenormalisedGradient>& grad,
                                            std::size_t n) {
  const double eta2 = ppe_eta2(f);
  std::vector<double> out(n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const RenormalisedGradient& g = grad[a];
    if (!g.regular) continue;
    double cx = 0, cy = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double r2, double, double F) {
      const double c = (f.m[b] / f.rho[b]) * 4.0 / (f.rho[a] + f.rho[b]) * F * r2 / (r2 + eta2);
      cx += c * rx;
      cy += c * ry;
    });
    out[a] = cx * g.x + cy * g.y;
  }
  return out;
}

}  // namespace arksph
