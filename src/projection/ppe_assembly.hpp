// The pressure Poisson equation of the approximate projection (Cummins & Rudman 1999 §2.3-2.5):
//
//   L(P)_a = sum_b (m_b/rho_b) 4/(rho_a + rho_b) (P_a - P_b) (r_ab . grad_a W_ab)/(r_ab^2 + eta^2)
//          = div(u*)_a / dt                                        (C&R eqs. 10 and 19; Szewc eq. 33)
//
// with eta^2 = 0.01 h^2, over real neighbours and ghosts; a ghost's pressure is its source's
// (homogeneous Neumann walls, C&R §2.5), so its coefficient lands in the source's column. The
// divergence is C&R eq. 17 over real neighbours only (ghosts left out, C&R §2.5), so that its sum
// over particles vanishes when m/rho is uniform (solvability, C&R eq. 23).
//
// Null space: with Neumann walls and periodic sides L annihilates constants. The source is shifted
// to zero mean (exact solvability also for unequal volumes), the equation of particle 0 is replaced
// by P_0 = 0 (row and column, keeping symmetry), and the solution is shifted to zero mean.
// Each row is multiplied by -V_a = -m_a/rho_a: the matrix becomes symmetric positive definite.
#pragma once
#include <vector>

#include "projection/poisson/poisson_solver.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

// div(u)_a of C&R eq. 17 for every real particle, real neighbours only.
std::vector<double> divergence_cummins_rudman(const FluidFields& f);

// A free surface (fluid.region): the particles where P is given (Shao & Lo 2003: p = 0 on the
// surface), each with its value. Empty: none, the Neumann problem above.
struct DirichletRows {
  std::vector<char> fixed;     // per real particle: 1 where P is given
  std::vector<double> value;   // P there
  bool empty() const { return fixed.empty(); }
};

// The surface particles, found by the divergence of position (Lind et al. 2012 §2.3):
//   div r_a = -sum_b V_b r_ab . grad_a W_ab   over real neighbours and wall images,
// d in the bulk of a d-dimensional fluid and about half of it at a free surface, where the kernel's
// support is cut; a particle is on the surface below `threshold` (Lind et al.: 1.5 in 2D). Wall
// images stand in for fluid, so a particle at a wall is not on the surface.
std::vector<char> free_surface_particles(const FluidFields& f, double threshold);
// The threshold the projection and the frames' free_surface array use: 0.75 d (1.5 in 2D).
inline double free_surface_threshold(int dimension) { return 0.75 * dimension; }
std::vector<double> position_divergence(const FluidFields& f);

struct PoissonSystem {
  SparseMatrix A;         // -V L with particle 0 pinned
  std::vector<double> b;  // -V div(u*)/dt, zero-mean source, b_0 = 0
};

// Assembles the system at the current fields. rho: density per point used in eq. 19 (each
// particle's own density; two-phase flows use unequal values).
PoissonSystem assemble_ppe(const FluidFields& f, const std::vector<double>& divergence, double dt);
// The same into an existing system, reusing its storage (no page faults on the matrix each step).
void assemble_ppe(const FluidFields& f, const std::vector<double>& divergence, double dt, PoissonSystem& sys);
// With rows of given P (a free surface): those rows read P_a = value_a, their columns move to the
// source of the others (A stays symmetric positive definite), and there is no null space: no pinned
// unknown, no shift of the source to zero mean.
void assemble_ppe(const FluidFields& f, const std::vector<double>& divergence, double dt, const DirichletRows& given,
                  PoissonSystem& sys);

// The Neumann data of the wall points under a body force (FluidFields::ghost_dp): a wall point's
// pressure is P_src + rho ghost_dp, so L(P)_a = s_a reads L0(P)_a = s_a + sum_b c_ab rho_b ghost_dp_b
// with L0 the matrix of assemble_ppe (wall points carrying their source's P). Returns that sum per
// real particle, to be added to div(u*)/dt (zeros without body force). Own mirror images count here
// (their P differs from the source's by the step), though they drop out of L0.
std::vector<double> neumann_source(const FluidFields& f);
// The same for the exact operator D G (assemble_ppe_exact): -D(G_step), G_step the gradient of the
// steps alone.
std::vector<double> neumann_source_exact(const FluidFields& f);

// The approximate Laplacian of C&R eq. 19 applied to a pressure field (real particles, ghosts
// mirror their source): for tests and residual checks.
std::vector<double> apply_laplacian(const FluidFields& f, const std::vector<double>& p);

}  // namespace arksph

namespace arksph {

// The exact projection operator of C&R eq. 18, (DG)P_i = sum_j V_j (sum_l V_l P_l grad_j W_jl) .
// grad_i W_ij, built as the product of the SPH divergence (real neighbours, C&R §2.5) and the SPH
// gradient (ghosts carrying their source's pressure). Its stencil reaches two kernel radii and it
// decouples odd and even particles (C&R Fig. 1a); kept for that comparison. Same scaling, source
// and pinning as assemble_ppe, but not symmetric: solve it with KLU.
PoissonSystem assemble_ppe_exact(const FluidFields& f, const std::vector<double>& divergence, double dt);

}  // namespace arksph

namespace arksph {

// The velocity divergence in difference form (the continuity operator of Szewc eq. 19 divided by
// rho_a): div(u)_a = -(1/rho_a) sum_b m_b (u_a - u_b) . grad_a W_ab over real neighbours AND ghosts
// (with their divergence velocities: free-slip images with boundary.free_slip_divergence). It
// vanishes for a uniform field even where the support is cut by a wall, which C&R eq. 17 with the
// ghosts left out does not: next to the corners of a driven lid that spurious source makes the
// projection unstable. Sums to zero only approximately; assemble_ppe removes the mean.
std::vector<double> divergence_difference(const FluidFields& f);

}  // namespace arksph
