// The corrections of C&R's projection after a step, shared by the one-process projection and the
// decomposed one. The velocity correction (Cummins & Rudman 1999 eq. 11):
//   u_a <- u_a - dt sum_b m_b (P_a / rho_a^2 + P_b / rho_b^2) grad_a W_ab
// over the stored pairs of the real particles [0, n). P holds a value per real point of f; ghosts
// read their source's value (plus the hydrostatic step under a body force: FluidFields::point_pressure).
// (The decomposed projection passes its halo's P after its own.)
// steps = false: ghosts read their source's value only (a potential, not a pressure: the
// constrained projection's start).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/particles.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

inline void subtract_pressure_gradient(const FluidFields& f, const std::vector<double>& p, double dt, std::size_t n,
                                       double* u, double* v, bool steps = true) {
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const double pa = p[a] / (f.rho[a] * f.rho[a]);
    double gx = 0, gy = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double pb = (steps ? f.point_pressure(p, b) : p[f.src[b]]) / (f.rho[b] * f.rho[b]);
      const double c = f.m[b] * (pb + pa) * F;
      gx += c * rx;
      gy += c * ry;
    });
    u[a] -= dt * gx;
    if (v) v[a] -= dt * gy;
  }
}

// The renormalised difference gradient (Randles & Libersky 1996; Bonet & Lok 1999) of P at a,
//   grad P_a = B_a sum_b V_b (P_b - P_a) grad_a W_ab,   B_a = (-sum_b V_b r_ab (x) grad_a W_ab)^-1,
// over real neighbours and ghosts (P as in subtract_pressure_gradient: a value per real point,
// ghosts their source's plus the hydrostatic step). It is exact for a linear P at any support, also
// one a free surface cuts. Where B_a's matrix is near-singular (det below kSingularMoment; 1 in the
// bulk, 1/4 at a flat surface, 1/16 at a right-angled corner of the fluid: a particle with a few
// neighbours on one side) the plain difference form without B_a, and regular = false.
constexpr double kSingularMoment = 0.02;
struct RenormalisedGradient {
  double x = 0, y = 0;
  bool regular = false;
};
// steps = false: ghosts take their source's P alone (a potential, not a pressure under a body force).
inline RenormalisedGradient renormalised_gradient(const FluidFields& f, const std::vector<double>& p, std::size_t a,
                                                  bool steps = true) {
  double gx = 0, gy = 0, mxx = 0, mxy = 0, myy = 0;
  f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
    const double vb = f.m[b] / f.rho[b];
    const double dp = (steps ? f.point_pressure(p, b) : p[f.src[b]]) - p[a];
    gx += vb * dp * F * rx;
    gy += vb * dp * F * ry;
    mxx -= vb * F * rx * rx;
    mxy -= vb * F * rx * ry;
    myy -= vb * F * ry * ry;
  });
  const bool two_d = f.dim == 2;
  const double det = two_d ? mxx * myy - mxy * mxy : mxx;
  if (!(det > kSingularMoment)) return {gx, two_d ? gy : 0.0, false};
  if (!two_d) return {gx / mxx, 0.0, true};
  return {(myy * gx - mxy * gy) / det, (mxx * gy - mxy * gx) / det, true};
}

// The renormalised gradient about the neighbours' own value at a:
//   grad P_a = B_a sum_b V_b (P_b - Pbar_a) grad_a W_ab,
// Pbar_a the value at r_a of the linear moving-least-squares fit to the neighbours' P, a itself left
// out (weights V_b W_ab). Exact for a linear P at any support (there Pbar_a = P_a, and this is the
// renormalised difference gradient above). P_a itself does not enter: the difference form's self
// term -P_a B_a sum_b V_b grad_a W_ab, non-zero where the support is cut, is what makes the
// projection at a surface amplify a particle-scale pattern (docs/methods/free-surface.md).
inline RenormalisedGradient neighbour_based_gradient(const FluidFields& f, const std::vector<double>& p, std::size_t a,
                                                     bool steps = true) {
  double gx = 0, gy = 0, sx = 0, sy = 0, bxx = 0, bxy = 0, byy = 0;
  double m0 = 0, m1x = 0, m1y = 0, mxx = 0, mxy = 0, myy = 0, q0 = 0, qx = 0, qy = 0;
  f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double r2, double w, double F) {
    const double vb = f.m[b] / f.rho[b];
    const double pb = steps ? f.point_pressure(p, b) : p[f.src[b]];
    gx += vb * pb * F * rx;
    gy += vb * pb * F * ry;
    sx += vb * F * rx;
    sy += vb * F * ry;
    bxx -= vb * F * rx * rx;
    bxy -= vb * F * rx * ry;
    byy -= vb * F * ry * ry;
    if (!(r2 > 0)) return;
    const double c = vb * w, ex = -rx, ey = -ry;  // r_b - r_a
    m0 += c;
    m1x += c * ex;
    m1y += c * ey;
    mxx += c * ex * ex;
    mxy += c * ex * ey;
    myy += c * ey * ey;
    q0 += c * pb;
    qx += c * ex * pb;
    qy += c * ey * pb;
  });
  const double det = bxx * byy - bxy * bxy, det2 = mxx * myy - mxy * mxy;
  if (f.dim != 2 || !(det > kSingularMoment) || !(det2 > 0)) return renormalised_gradient(f, p, a, steps);
  const double ix = (myy * m1x - mxy * m1y) / det2, iy = (mxx * m1y - mxy * m1x) / det2;  // M2^-1 m1
  const double rest = m0 - (m1x * ix + m1y * iy);
  if (!(rest > 0)) return renormalised_gradient(f, p, a, steps);
  const double pbar = (q0 - (ix * qx + iy * qy)) / rest;
  const double hx = gx - pbar * sx, hy = gy - pbar * sy;
  return {(byy * hx - bxy * hy) / det, (bxx * hy - bxy * hx) / det, true};
}

// The renormalised gradient at each of the first n particles.
inline std::vector<RenormalisedGradient> renormalised_gradients(const FluidFields& f, const std::vector<double>& p,
                                                                std::size_t n) {
  std::vector<RenormalisedGradient> out(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) out[a] = renormalised_gradient(f, p, a);
  return out;
}

// The velocity correction at a free surface (fluid.region): u_a <- u_a - dt grad P_a / rho_a with
// a gradient exact for a linear P at a cut support, where C&R eq. 11's symmetric sum turns
// P_a sum_b m_b grad W_ab into a force: at the surface rows (`surface`: the rows of given P) the
// renormalised difference gradient, below them the neighbour-based one. Below the surface the
// difference form's self term makes the projection amplify the second row's odd-even motion at
// every projection (by 1.019 a projection at h = 2 dx); at the surface rows the neighbour-based
// gradient lets the column at rest of docs/methods/free-surface.md start moving at its top corners
// after t ~ 7, which the renormalised one there does not.
inline void subtract_renormalised_gradient(const FluidFields& f, const std::vector<double>& p, double dt,
                                           std::size_t n, double* u, double* v, const std::vector<char>& surface,
                                           bool steps = true) {
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const RenormalisedGradient g =
        surface[a] ? renormalised_gradient(f, p, a, steps) : neighbour_based_gradient(f, p, a, steps);
    u[a] -= dt * g.x / f.rho[a];
    if (v) v[a] -= dt * g.y / f.rho[a];
  }
}

// The positions centred in time (C&R eq. 12) from the step's start y_prev (the whole state at
// r^n) and the projected velocities of y:
//   r_a <- r_a^n + dt (u_a^{n+1} + u_a^n) / 2 + dt du_s,a
// where du_s is the regularisation velocity of f (shift_u, shift_v; none when they are empty),
// computed at r* by the projection's evaluation.
inline void centre_positions(const StateLayout& L, const FluidFields& f, const std::vector<double>& y_prev, double dt,
                             double* y) {
  for (int k = 0; k < L.dim; ++k) {
    const std::vector<double>& shift = k == 0 ? f.shift_u : f.shift_v;
    for (std::size_t a = 0; a < L.n; ++a) {
      const double u_new = y[L.vel(k) + a], u_old = y_prev[L.vel(k) + a];
      y[L.pos(k) + a] = y_prev[L.pos(k) + a] + dt * 0.5 * (u_new + u_old);
      if (!shift.empty()) y[L.pos(k) + a] += dt * shift[a];
    }
  }
}

}  // namespace arksph
