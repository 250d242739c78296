#include "projection/ppe_assembly.hpp"

#include <cmath>
#include <numeric>

#include "kernels/kernel.hpp"
#include "projection/ppe_row.hpp"

namespace arksph {

std::vector<double> divergence_cummins_rudman(const FluidFields& f) {
  std::vector<double> div(f.n_real, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < f.n_real; ++a) {
    double s = 0;
    const double rho_a = f.rho[a];
    const double ua = f.u[a] / (rho_a * rho_a), va = f.dim == 2 ? f.v[a] / (rho_a * rho_a) : 0.0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      if (f.is_wall_image(b)) return;  // wall ghosts left out (C&R §2.5); periodic images are neighbours
      const double rb2 = f.rho[b] * f.rho[b];
      const double ux = f.u[b] / rb2 + ua, uy = f.dim == 2 ? f.v[b] / rb2 + va : 0.0;
      s += f.m[b] * F * (ux * rx + uy * ry);  // m_b (u_b/rho_b^2 + u_a/rho_a^2) . grad_a W_ab
    });
    div[a] = rho_a * s;  // C&R eq. 17
  }
  return div;
}

std::vector<double> neumann_source(const FluidFields& f) {
  std::vector<double> out(f.n_real, 0.0);
  if (f.ghost_dp.empty()) return out;
  const double eta2 = ppe_eta2(f);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < f.n_real; ++a) {
    double s = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double, double, double r2, double, double F) {
      if (f.ghost_dp[b] != 0.0) s += laplacian_coeff(f, a, b, r2, F, eta2) * f.rho[b] * f.ghost_dp[b];
    });
    out[a] = s;
  }
  return out;
}

std::vector<double> neumann_source_exact(const FluidFields& f) {
  std::vector<double> out(f.n_real, 0.0);
  if (f.ghost_dp.empty()) return out;
  std::vector<double> gx(f.n_real, 0.0), gy(f.n_real, 0.0);
  for (std::size_t a = 0; a < f.n_real; ++a)
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      if (f.ghost_dp[b] == 0.0) return;
      const double c = f.m[b] / f.rho[b] * F * f.rho[b] * f.ghost_dp[b];
      gx[a] += c * rx;
      gy[a] += c * ry;
    });
  for (std::size_t a = 0; a < f.n_real; ++a)
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      if (f.is_wall_image(b)) return;
      const std::uint32_t s = f.src[b];
      out[a] -= f.m[b] / f.rho[b] * F * (gx[s] * rx + gy[s] * ry);
    });
  return out;
}

std::vector<double> apply_laplacian(const FluidFields& f, const std::vector<double>& p) {
  const double eta2 = ppe_eta2(f);
  std::vector<double> out(f.n_real, 0.0);
  for (std::size_t a = 0; a < f.n_real; ++a) {
    double s = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double, double, double r2, double, double F) {
      s += laplacian_coeff(f, a, b, r2, F, eta2) * (p[a] - p[f.src[b]]);
    });
    out[a] = s;
  }
  return out;
}

PoissonSystem assemble_ppe(const FluidFields& f, const std::vector<double>& divergence, double dt) {
  PoissonSystem sys;
  assemble_ppe(f, divergence, dt, sys);
  return sys;
}

void assemble_ppe(const FluidFields& f, const std::vector<double>& divergence, double dt, PoissonSystem& sys) {
  assemble_ppe(f, divergence, dt, DirichletRows{}, sys);
}

std::vector<double> position_divergence(const FluidFields& f) {
  std::vector<double> div(f.n_real, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < f.n_real; ++a) {
    double s = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double, double, double r2, double, double F) {
      s += (f.m[b] / f.rho[b]) * F * r2;  // V_b r_ab . grad_a W_ab, grad_a W_ab = F r_ab
    });
    div[a] = -s;
  }
  return div;
}

namespace {
// Marrone et al. 2010's scan region, for a candidate a in 2D: the outward normal
// n = -B_a sum_b V_b grad_a W_ab / |...| (B_a the renormalisation matrix), T = r_a + h n; a lies on
// the surface when no neighbour b (wall images included) lies in the umbrella-shaped region
//   |r_ba| >= sqrt(2) h and |r_bT| < h,   or   |r_ba| < sqrt(2) h and |n . r_bT| + |tau . r_bT| < h.
// A particle next to a small void inside the fluid (div r low, but fluid across the void) is not.
// Where B_a is near-singular (det below 0.02 of its bulk value 1: a lone particle) it is.
bool empty_scan_region(const FluidFields& f, std::size_t a) {
  double cx = 0, cy = 0, mxx = 0, mxy = 0, myy = 0;
  f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
    const double vb = f.m[b] / f.rho[b];
    cx += vb * F * rx;
    cy += vb * F * ry;
    mxx -= vb * F * rx * rx;
    mxy -= vb * F * rx * ry;
    myy -= vb * F * ry * ry;
  });
  const double det = mxx * myy - mxy * mxy;
  if (!(det > 0.02)) return true;
  double nx = -(myy * cx - mxy * cy) / det, ny = -(mxx * cy - mxy * cx) / det;
  const double norm = std::hypot(nx, ny);
  if (!(norm > 0)) return false;  // a full support
  nx /= norm;
  ny /= norm;
  const double h = f.kernel->h(), wide = 2 * h * h;
  bool empty = true;
  f.pairs.for_pairs(a, [&](std::uint32_t, double rx, double ry, double r2, double, double) {
    const double tx = -rx - h * nx, ty = -ry - h * ny;  // r_b - r_T, r_ab = r_a - r_b
    const bool inside = r2 >= wide ? tx * tx + ty * ty < h * h
                                   : std::abs(nx * tx + ny * ty) + std::abs(-ny * tx + nx * ty) < h;
    if (inside) empty = false;
  });
  return empty;
}
}  // namespace

std::vector<char> free_surface_particles(const FluidFields& f, double threshold) {
  const std::vector<double> div = position_divergence(f);
  std::vector<char> surface(div.size());
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < div.size(); ++a)
    surface[a] = div[a] < threshold && (f.dim != 2 || empty_scan_region(f, a));
  return surface;
}

void assemble_ppe(const FluidFields& f, const std::vector<double>& divergence, double dt, const DirichletRows& given,
                  PoissonSystem& sys) {
  const std::size_t n = f.n_real;
  const double eta2 = ppe_eta2(f);
  const bool neumann = given.empty();
  const std::uint32_t pinned = neumann ? 0 : static_cast<std::uint32_t>(-1);  // P_0 = 0 without given rows
  // Source: zero mean (Neumann only), scaled like the rows.
  const double mean =
      neumann ? std::accumulate(divergence.begin(), divergence.end(), 0.0) / static_cast<double>(n) : 0.0;
  sys.b.resize(n);
  for (std::size_t a = 0; a < n; ++a) sys.b[a] = -(f.m[a] / f.rho[a]) * (divergence[a] - mean) / dt;
  if (neumann) sys.b[0] = 0.0;
  // Matrix, built in compressed form without triplets: row a holds its coefficients by source
  // column, several (periodic or wall) images of one source merged. A is symmetric, so row a is
  // stored as column a of the column-major matrix (A^T, equal to A up to round-off). Each row gets
  // room for its pair count plus the diagonal, is filled, sorted by column and merged in place
  // (rows in parallel); makeCompressed() then closes the gaps. The storage of sys.A is reused.
  SparseMatrix& A = sys.A;
  A.resize(static_cast<long>(n), static_cast<long>(n));
  Eigen::VectorXi room(static_cast<long>(n));
  for (std::size_t a = 0; a < n; ++a) room[static_cast<long>(a)] = static_cast<int>(f.pairs.count[a]) + 1;
  A.reserve(room);
  const int* start = A.outerIndexPtr();
  int* used = A.innerNonZeroPtr();
  int* inner = A.innerIndexPtr();
  double* value = A.valuePtr();
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t a = 0; a < n; ++a) {
    int* col = inner + start[a];
    double* val = value + start[a];
    int len = 0;
    const bool fixed_row = a == pinned || (!neumann && given.fixed[a]);
    double moved = 0;  // given P of the columns dropped, carried to the source
    const double diag = ppe_row(f, a, eta2, [](std::uint32_t s) { return s; }, [&](std::uint32_t s, double v) {
      if (fixed_row || s == pinned) return;  // P_0 = 0: row and column 0 dropped
      if (!neumann && given.fixed[s]) {
        moved += v * given.value[s];
        return;
      }
      col[len] = static_cast<int>(s);
      val[len++] = v;
    });
    col[len] = static_cast<int>(a);
    val[len++] = close_row(a == pinned, fixed_row, diag, neumann ? 0.0 : given.value[a], moved, sys.b[a]);
    const int m = sort_merge_row(col, val, len);
    used[a] = m;
  }
  A.makeCompressed();
}

}  // namespace arksph

namespace arksph {

PoissonSystem assemble_ppe_exact(const FluidFields& f, const std::vector<double>& divergence, double dt) {
  const std::size_t n = f.n_real;
  const int dims = f.dim;
  using Trip = Eigen::Triplet<double, int>;
  std::vector<Trip> g[2], d[2];
  for (std::size_t a = 0; a < n; ++a) {
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double vb = f.m[b] / f.rho[b];
      const double r[2] = {rx, ry};
      for (int k = 0; k < dims; ++k) {
        // G: row a, column src(b): V_b grad_a W_ab (pressure of ghost b is its source's)
        g[k].emplace_back(static_cast<int>(a), static_cast<int>(f.src[b]), vb * F * r[k]);
        // D: row a, column src(b) for real b and periodic images (wall ghosts left out): V_b grad_a W_ab
        if (!f.is_wall_image(b)) d[k].emplace_back(static_cast<int>(a), static_cast<int>(f.src[b]), vb * F * r[k]);
      }
    });
  }
  SparseMatrix lap(static_cast<long>(n), static_cast<long>(n));
  for (int k = 0; k < dims; ++k) {
    SparseMatrix G(static_cast<long>(n), static_cast<long>(n)), D(static_cast<long>(n), static_cast<long>(n));
    G.setFromTriplets(g[k].begin(), g[k].end());
    D.setFromTriplets(d[k].begin(), d[k].end());
    lap += SparseMatrix(D * G);
  }
  // Rows scaled by -V_a like assemble_ppe; particle 0 pinned.
  PoissonSystem sys;
  const double mean = std::accumulate(divergence.begin(), divergence.end(), 0.0) / static_cast<double>(n);
  sys.b.resize(n);
  std::vector<Trip> trip;
  for (int col = 0; col < lap.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(lap, col); it; ++it) {
      const auto row = static_cast<std::size_t>(it.row());
      if (row == 0 || it.col() == 0) continue;
      trip.emplace_back(it.row(), it.col(), -(f.m[row] / f.rho[row]) * it.value());
    }
  trip.emplace_back(0, 0, 1.0);
  for (std::size_t a = 0; a < n; ++a) sys.b[a] = -(f.m[a] / f.rho[a]) * (divergence[a] - mean) / dt;
  sys.b[0] = 0.0;
  sys.A.resize(static_cast<long>(n), static_cast<long>(n));
  sys.A.setFromTriplets(trip.begin(), trip.end());
  sys.A.makeCompressed();
  return sys;
}

}  // namespace arksph

namespace arksph {

std::vector<double> divergence_difference(const FluidFields& f) {
  std::vector<double> div(f.n_real, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < f.n_real; ++a) {
    double s = 0;
    const double ua = f.ud[a], va = f.dim == 2 ? f.vd[a] : 0.0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double du = ua - f.ud[b], dv = f.dim == 2 ? va - f.vd[b] : 0.0;
      s += f.m[b] * F * (du * rx + dv * ry);
    });
    div[a] = -s / f.rho[a];
  }
  return div;
}

}  // namespace arksph
