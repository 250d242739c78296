#include "projection/divergence_operator.hpp"

#include <cmath>

#include "kernels/kernel.hpp"


namespace arksph {

namespace {
// The velocity component k of point b as the divergence sees it: its source's, reflected where b is
// a mirror image across a wall (free slip), unchanged for periodic images.
inline double flip(const std::vector<double>& s, std::size_t b) { return s.empty() ? 1.0 : s[b]; }
}  // namespace

void DivergenceOperator::assemble(const FluidFields& f) {
  dim_ = f.dim;
  n_ = f.n_real;
  const auto n = static_cast<long>(n_);
  vol_.resize(n_);
  mass_.resize(n_);
  for (std::size_t a = 0; a < n_; ++a) {
    mass_[a] = f.m[a];
    vol_[a] = f.m[a] / f.rho[a];
  }
  // Row a of D_k: V_b e_ab,k R_b,k in the source's column, -sum_b V_b e_ab,k in column a. Rows are
  // filled in pair order and summed by Eigen's compression (duplicates of one source merge).
  for (int k = 0; k < dim_; ++k) {
    d_[k].resize(n, n);
    Eigen::VectorXi room(n);
    for (std::size_t a = 0; a < n_; ++a) room[static_cast<long>(a)] = static_cast<int>(f.pairs.count[a]) + 1;
    d_[k].reserve(room);
  }
  std::vector<double> diag(static_cast<std::size_t>(dim_));
  for (std::size_t a = 0; a < n_; ++a) {
    diag.assign(static_cast<std::size_t>(dim_), 0.0);
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double vb = f.m[b] / f.rho[b];
      const double e[2] = {vb * F * rx, vb * F * ry};
      const double sign[2] = {flip(f.flip_x, b), flip(f.flip_y, b)};
      for (int k = 0; k < dim_; ++k) {
        d_[k].coeffRef(static_cast<long>(a), static_cast<long>(f.src[b])) += e[k] * sign[k];
        diag[static_cast<std::size_t>(k)] -= e[k];
      }
    });
    for (int k = 0; k < dim_; ++k) d_[k].coeffRef(static_cast<long>(a), static_cast<long>(a)) += diag[static_cast<std::size_t>(k)];
  }
  for (int k = 0; k < dim_; ++k) {
    d_[k].makeCompressed();
    row_abs_[k].assign(n_, 0.0);
    for (long a = 0; a < n; ++a)
      for (RowMatrix::InnerIterator it(d_[k], a); it; ++it) row_abs_[k][static_cast<std::size_t>(a)] += std::abs(it.value());
  }
  k_built_ = false;
}

const SparseMatrix& DivergenceOperator::normal_matrix() {
  if (k_built_) return k_;
  // K = sum_k B_k B_k^T with B_k = V D_k M^-1/2.
  const auto n = static_cast<long>(n_);
  Eigen::VectorXd v(n), s(n);
  for (std::size_t a = 0; a < n_; ++a) {
    v[static_cast<long>(a)] = vol_[a];
    s[static_cast<long>(a)] = 1.0 / std::sqrt(mass_[a]);
  }
  k_.resize(n, n);
  k_.setZero();
  for (int k = 0; k < dim_; ++k) {
    const RowMatrix b = v.asDiagonal() * d_[k] * s.asDiagonal();
    k_ += SparseMatrix(b * SparseMatrix(b.transpose()));
  }
  k_.makeCompressed();
  k_built_ = true;
  return k_;
}

void DivergenceOperator::divergence(const double* u, const double* v, double* out) const {
  const auto n = static_cast<long>(n_);
  Eigen::Map<const Eigen::VectorXd> ux(u, n);
  Eigen::Map<Eigen::VectorXd> o(out, n);
  o = d_[0] * ux;
  if (dim_ == 2) o += d_[1] * Eigen::Map<const Eigen::VectorXd>(v, n);
}

void DivergenceOperator::gradient(const double* p, double* gx, double* gy) const {
  const auto n = static_cast<long>(n_);
  Eigen::VectorXd vp(n);
  for (long a = 0; a < n; ++a) vp[a] = vol_[static_cast<std::size_t>(a)] * p[a];
  for (int k = 0; k < dim_; ++k) {
    Eigen::Map<Eigen::VectorXd> g(k == 0 ? gx : gy, n);
    g = d_[k].transpose() * vp;
    for (long a = 0; a < n; ++a) g[a] = -g[a] / mass_[static_cast<std::size_t>(a)];
  }
}

std::vector<double> divergence_rate_of_motion(const FluidFields& f, const double* u, const double* v) {
  std::vector<double> q(f.n_real, 0.0);
  const Kernel& kernel = *f.kernel;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < f.n_real; ++a) {
    double s = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double r2, double, double F) {
      if (!(r2 > 0)) return;
      const std::uint32_t src = f.src[b];
      const double ub = flip(f.flip_x, b) * u[src];
      const double vb = f.dim == 2 ? flip(f.flip_y, b) * v[src] : 0.0;
      const double dux = u[a] - ub, duy = f.dim == 2 ? v[a] - vb : 0.0;
      const double r = std::sqrt(r2);
      const double along = (dux * rx + duy * ry) / r;
      // u^T H u = W'' (u . rhat)^2 + (W'/r) (|u|^2 - (u . rhat)^2)
      const double quad = kernel.d2Wdr2(r) * along * along + F * (dux * dux + duy * duy - along * along);
      s += f.m[b] / f.rho[b] * quad;
    });
    q[a] = s;
  }
  return q;
}

void divergence_minus_motion(const FluidFields& f, const double* wx, const double* wy, const double* u, const double* v,
                             double* out) {
  const Kernel& kernel = *f.kernel;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < f.n_real; ++a) {
    const double wxa = wx[a], wya = f.dim == 2 ? wy[a] : 0.0;
    const double ua = u[a], va = f.dim == 2 ? v[a] : 0.0;
    double s = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double r2, double, double F) {
      if (!(r2 > 0)) return;
      const std::uint32_t src = f.src[b];
      const double fx = flip(f.flip_x, b), fy = flip(f.flip_y, b);
      const double wxb = fx * wx[src], wyb = f.dim == 2 ? fy * wy[src] : 0.0;
      const double dux = ua - fx * u[src], duy = f.dim == 2 ? va - fy * v[src] : 0.0;
      const double r = std::sqrt(r2);
      const double along = (dux * rx + duy * ry) / r;
      const double quad = kernel.d2Wdr2(r) * along * along + F * (dux * dux + duy * duy - along * along);
      s += f.m[b] / f.rho[b] * (F * ((wxb - wxa) * rx + (wyb - wya) * ry) - quad);
    });
    out[a] = s;
  }
}

void difference_divergence(const FluidFields& f, const double* wx, const double* wy, double* out) {
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < f.n_real; ++a) {
    const double xa = wx[a], ya = f.dim == 2 ? wy[a] : 0.0;
    double s = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const std::uint32_t src = f.src[b];
      const double xb = flip(f.flip_x, b) * wx[src];
      const double yb = f.dim == 2 ? flip(f.flip_y, b) * wy[src] : 0.0;
      s += f.m[b] / f.rho[b] * F * ((xb - xa) * rx + (yb - ya) * ry);
    });
    out[a] = s;
  }
}

double divergence_rms(const FluidFields& f, const double* u, const double* v) {
  std::vector<double> d(f.n_real);
  difference_divergence(f, u, v, d.data());
  double s = 0, vs = 0;
  for (std::size_t a = 0; a < f.n_real; ++a) {
    const double vol = f.m[a] / f.rho[a];
    s += vol * d[a] * d[a];
    vs += vol;
  }
  return std::sqrt(s / vs);
}

void convective_acceleration(const FluidFields& f, const double* u, const double* v, std::vector<double>& cx,
                             std::vector<double>& cy) {
  const std::size_t n = f.n_real;
  cx.assign(n, 0.0);
  cy.assign(n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    double gxx = 0, gxy = 0, gyx = 0, gyy = 0;  // g_kl = d u_k / d x_l
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const std::uint32_t src = f.src[b];
      const double vb = f.m[b] / f.rho[b];
      const double du = flip(f.flip_x, b) * u[src] - u[a];
      const double dv = f.dim == 2 ? flip(f.flip_y, b) * v[src] - v[a] : 0.0;
      gxx += vb * du * F * rx;
      gxy += vb * du * F * ry;
      gyx += vb * dv * F * rx;
      gyy += vb * dv * F * ry;
    });
    const double va = f.dim == 2 ? v[a] : 0.0;
    cx[a] = u[a] * gxx + va * gxy;
    cy[a] = u[a] * gyx + va * gyy;
  }
}

}  // namespace arksph
