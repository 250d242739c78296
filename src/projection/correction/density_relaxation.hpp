// The Pozorski-Wawrenczuk correction as a velocity inside f(t, y), for the constrained projection.
//
// Szewc et al. 2012 eqs. 57-59 shift the particles after a step by dr = -G p* / rho0 so that the
// summation density (eq. 21) returns to rho0. A position change after the step is outside the ODE
// and voids ARKODE's order, so here the same displacement becomes a rate:
//
//   dr_a/dt += kappa dr_a,   kappa = gamma U / h   (gamma = method.correction_relaxation),
//
// with dr the Newton direction of projection/correction/correction_newton.hpp: K p* = -(s - mean s), K the
// exact derivative of s_a = 1 - (m_a/rho0_a) sum_b W_ab along the shift. To first order
// ds/dt = kappa K p* = -kappa (s - mean s): the density fluctuation decays at the rate kappa on every
// scale the truncated Krylov solve resolves. (With C&R's approximate Laplacian in place of K, as in
// eq. 58, particle-scale errors, where that Laplacian is stiffer than K, barely decay: measured on the
// spin-down, CV(10) 0.009 against 0.0136 without the correction, whatever gamma.)
// Each particle's shift saturates smoothly at a tenth of the spacing, dr <- dr / sqrt(1 + |dr|^2 /
// (0.1 dx)^2), as the step-wise correction clips it. The velocity of a shifted particle is not
// corrected (Szewc's step moves the positions only); the constraint's relaxation absorbs the
// divergence the shift makes.
#pragma once
#include <cstdint>
#include <vector>

#include "core/scene.hpp"
#include "projection/correction/correction_newton.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

class DensityRelaxation {
 public:
  // rate: kappa, in 1/s.
  DensityRelaxation(const Scene& scene, double rate);
  // Adds kappa dr to (xdot, ydot) (ydot null in 1D) at the fields of the last eval; returns the
  // Krylov iterations.
  int add_velocity(const FluidFields& f, double* xdot, double* ydot) { return add_velocity(f, local_span(f), xdot, ydot); }
  // The same for the span's own particles (one rank of a decomposed run: sums over the ranks, the
  // halo copies' values from their owners; projection/correction/correction_newton.hpp).
  int add_velocity(const FluidFields& f, const CorrectionSpan& span, double* xdot, double* ydot);
  double rate() const { return rate_; }
  // r.m.s. of the density fluctuation at the last add_velocity (Szewc eq. 56).
  double last_error() const { return last_error_; }

 private:
  double rate_;
  double cap_;
  double last_error_ = 0;
  std::vector<double> s_, p_, dx_, dy_;
};

}  // namespace arksph
