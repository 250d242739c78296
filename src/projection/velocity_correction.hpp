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
struct RenormalisedGradient {
  double x = 0, y = 0;
  bool regular = false;
};
inline RenormalisedGradient renormalised_gradient(const FluidFields& f, const std::vector<double>& p, std::size_t a) {
  constexpr double kSingularMoment = 0.02;
  double gx = 0, gy = 0, mxx = 0, mxy = 0, myy = 0;
  f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
    const double vb = f.m[b] / f.rho[b];
    const double dp = f.point_pressure(p, b) - p[a];
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

// The renormalised gradient at each of the first n particles.
inline std::vector<RenormalisedGradient> renormalised_gradients(const FluidFields& f, const std::vector<double>& p,
                                                                std::size_t n) {
  std::vector<RenormalisedGradient> out(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) out[a] = renormalised_gradient(f, p, a);
  return out;
}

// The velocity correction at a free surface (fluid.region): u_a <- u_a - dt grad P_a / rho_a with
// the renormalised gradient above, where C&R eq. 11's symmetric sum turns P_a sum_b m_b grad W_ab,
// non-zero at a cut support, into a force.
inline void subtract_renormalised_gradient(const FluidFields& f, const std::vector<double>& p, double dt,
                                           std::size_t n, double* u, double* v) {
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const RenormalisedGradient g = renormalised_gradient(f, p, a);
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
