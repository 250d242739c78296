#include "projection/free_surface.hpp"

#include "projection/ppe_row.hpp"

namespace arksph {

DirichletRows surface_rows(const FluidFields& f, std::size_t n, double threshold) {
  DirichletRows given;
  given.fixed = free_surface_particles(f, threshold);
  given.fixed.resize(n);
  given.value.assign(n, 0.0);
  return given;
}

std::vector<double> linear_laplacian_defect(const FluidFields& f, const std::vector<double>& p, std::size_t n) {
  // As in subtract_renormalised_gradient: below this determinant of the moment matrix (1 in the
  // bulk, 1/4 at a flat surface) the gradient is not renormalised, and no defect is taken.
  constexpr double kSingularMoment = 0.02;
  const double eta2 = ppe_eta2(f);
  std::vector<double> out(n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    double gx = 0, gy = 0, mxx = 0, mxy = 0, myy = 0, cx = 0, cy = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double r2, double, double F) {
      const double vb = f.m[b] / f.rho[b];
      const double dp = f.point_pressure(p, b) - p[a];
      gx += vb * dp * F * rx;
      gy += vb * dp * F * ry;
      mxx -= vb * F * rx * rx;
      mxy -= vb * F * rx * ry;
      myy -= vb * F * ry * ry;
      const double c = vb * 4.0 / (f.rho[a] + f.rho[b]) * F * r2 / (r2 + eta2);
      cx += c * rx;
      cy += c * ry;
    });
    if (f.dim == 2) {
      const double det = mxx * myy - mxy * mxy;
      if (det > kSingularMoment) out[a] = (cx * (myy * gx - mxy * gy) + cy * (mxx * gy - mxy * gx)) / det;
    } else if (mxx > kSingularMoment) {
      out[a] = cx * gx / mxx;
    }
  }
  return out;
}

}  // namespace arksph
