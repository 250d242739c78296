// Kernel consistency corrections of Basa, Quinlan & Lastiwka 2008 §4, as used by the pair terms.
//   Shepard (zero order, eqs. 21-22): W0_ab = W_ab / <1>_a, whose gradient with respect to r_a is
//     G0_ab = (grad W_ab - W_ab <grad 1>_a / <1>_a) / <1>_a,
//     <1>_a = sum_b V_b W_ab (self included), <grad 1>_a = sum_b V_b grad W_ab.
//   Bonet-Lok (first order, eqs. 24-26): G1_ab = L_a G0_ab, L_a = (sum_b V_b G0_ab (x) r_b)^-1.
// Since sum_b V_b G0_ab = 0 (self included), gradients are taken in the difference form
// sum_b V_b (F_b - F_a) G_ab, which is the same sum and needs no self term; the Bonet-Lok matrix is
// built from r_b - r_a for the same reason (round-off). Both reproduce the gradient of a constant
// exactly; Bonet-Lok also that of a linear field (test "kernel correction: ...").
#pragma once
#include <cstddef>

#include "rhs/fluid_fields.hpp"

namespace arksph {

// The gradient (gx, gy) that a pair term uses in place of grad_a W_ab = F r_ab, for the point i
// (real, or a ghost when the correction data covers all points), neighbour at r_ib = (rx, ry).
inline void corrected_gradient(const FluidFields& f, std::size_t i, double rx, double ry, double w, double F,
                               double& gx, double& gy) {
  gx = F * rx;
  gy = F * ry;
  if (f.correction == FluidFields::Correction::none) return;
  const double inv = 1.0 / f.one[i];
  gx = (gx - w * f.grad1x[i] * inv) * inv;
  gy = (gy - w * f.grad1y[i] * inv) * inv;
  if (f.correction == FluidFields::Correction::bonet_lok) {
    const double* L = &f.lmat[4 * i];
    const double tx = L[0] * gx + L[1] * gy;
    gy = L[2] * gx + L[3] * gy;
    gx = tx;
  }
}

// Shepard interpolation of a field at real particle a (eq. 21): sum_b V_b F_b W_ab / <1>_a.
double shepard_interpolate(const FluidFields& f, std::size_t a, const double* field);

}  // namespace arksph
