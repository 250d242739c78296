// The stiffness of Fickian particle shifting (rhs/regularisation/Shifting_Lind2012.cpp). The shifting velocity
// du_a = -A h U grad C_a, grad C_a = V0 sum_b (1 + R (W_ab / W(dx))^4) grad_a W_ab, diffuses the
// particle positions: for a small displacement field d_a about the lattice,
//   d(d_a)/dt = -A h U V0 sum_b J(r_ab) (d_a - d_b),   J(r) = Jacobian of (1 + R (W/W(dx))^4) grad W,
// and the Fourier mode d_a = d exp(i k . r_a) decays at the rates A h U eig(M(k)),
//   M(k) = V0 sum_b J(r_ab) (1 - cos k . r_ab).
// The fastest rate comes from the shortest waves the lattice carries (about 3 U A / h for the
// Wendland kernel at h = 2 dx): an explicit step above about 2 / rate amplifies the particle-scale
// noise that shifting is there to remove, and the saturation of du then holds it at a level that no
// longer falls with the resolution.
#pragma once
#include "kernels/kernel.hpp"

namespace arksph {

// The largest eigenvalue of M(k) over the wave numbers of the square (in 1D: linear) lattice of
// spacing dx, times h^2: the fastest decay rate of the linearised shifting is A U / h times this.
double shifting_stiffness(const Kernel& kernel, double dx, double anti_clumping);

}  // namespace arksph
