// The discrete divergence D and gradient G of the constrained projection (projection/ConstrainedPressure.hpp),
// built so that G is the negative adjoint of D:
//
//   (D u)_a = sum_b V_b (u_b - u_a) . grad_a W_ab          (difference form, exact for uniform u)
//   G p     = -M^-1 D^T V p,   i.e. <u, G p>_m = -<D u, p>_V
//
// with <u, w>_m = sum_a m_a u_a . w_a and <p, q>_V = sum_a V_a p_a q_a, V_a = m_a / rho_a. Far from
// walls G p is the symmetric (sum) form (1/rho_a) sum_b V_b (p_a + p_b) grad_a W_ab. The sum over b
// runs over real neighbours, periodic images and wall images; a wall image carries the free-slip
// reflection R_b u_src(b) of its source's velocity (each component flipped where the image is
// mirrored), so that G gives the wall image its source's pressure (homogeneous Neumann walls).
//
// Because G = -M^-1 D^T V, the projection P = I - G (D G)^-1 D is orthogonal in <.,.>_m, hence
// idempotent, and the pressure does no work on a divergence-free field: <u, G p>_m = 0 when D u = 0.
// The matrix of the pressure equation, K = V D M^-1 D^T V = -V D G, is symmetric positive
// semidefinite. Its null space is ker G: on a uniform lattice the constants and the odd-even modes;
// the right-hand side V D(.) is orthogonal to it, so the system is consistent and conjugate
// gradients solve it.
#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/SparseCore>

#include "projection/poisson/poisson_solver.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

class DivergenceOperator {
 public:
  // The operators at the positions of `f` (its pair list, ghosts and volumes).
  void assemble(const FluidFields& f);
  std::size_t size() const { return n_; }
  int dimension() const { return dim_; }
  // out = D u for real velocities (u, v); v unused in 1D.
  void divergence(const double* u, const double* v, double* out) const;
  // (gx, gy) = G p = -M^-1 D^T V p; gy unused in 1D.
  void gradient(const double* p, double* gx, double* gy) const;
  // K = V D M^-1 D^T V (column-major, both triangles), built at the first call after assemble().
  const SparseMatrix& normal_matrix();
  const std::vector<double>& volume() const { return vol_; }
  // D's rows for velocity component k (n x n, real particles).
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  const RowMatrix& component(int k) const { return d_[k]; }
  // sum_b |D_ab| of component k's row a: the size of the terms that make (D u)_a, per unit |u|.
  const std::vector<double>& row_magnitude(int k) const { return row_abs_[k]; }

 private:
  int dim_ = 2;
  std::size_t n_ = 0;
  RowMatrix d_[2];  // D's rows by velocity component
  std::vector<double> vol_, mass_;
  std::vector<double> row_abs_[2];
  SparseMatrix k_;
  bool k_built_ = false;
};

// Q_a = sum_b V_b u_ab^T H_ab u_ab, u_ab = u_a - u_b (wall images: reflected velocities), H_ab the
// Hessian of W at r_ab: exactly the part of d(D u)/dt that the particles' motion makes,
// d(D u)/dt = D (du/dt) - Q along dr/dt = u with constant volumes (the discrete counterpart of
// div(du/dt) - tr(grad u grad u)).
std::vector<double> divergence_rate_of_motion(const FluidFields& f, const double* u, const double* v);

// out = D w - Q in one pass over the pairs (the source of the constrained projection's pressure
// equation), w the acceleration field, (u, v) the velocities that Q reads.
void divergence_minus_motion(const FluidFields& f, const double* wx, const double* wy, const double* u, const double* v,
                             double* out);

// out = D w, pair by pair (no matrix): the divergence of the constrained projection's source and of
// the run's incompressibility measure.
void difference_divergence(const FluidFields& f, const double* wx, const double* wy, double* out);
// (cx, cy) = (u . grad) u with the difference-form gradient (grad u)_a = sum_b V_b (u_b - u_a) (x)
// grad_a W_ab (wall images: reflected velocities): the convective acceleration, whose divergence
// D (u . grad) u = tr(grad u grad u) + u . grad(D u) stands for Q where D u = 0.
void convective_acceleration(const FluidFields& f, const double* u, const double* v, std::vector<double>& cx,
                             std::vector<double>& cy);
// r.m.s. of D u over the real particles, volume weighted.
double divergence_rms(const FluidFields& f, const double* u, const double* v);

}  // namespace arksph
