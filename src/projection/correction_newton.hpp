// The Pozorski-Wawrenczuk correction (Szewc et al. 2012 eqs. 57-59) as an inexact Newton iteration on
// the summation density itself, with its exact derivative (method.correction_solver = "newton").
//
// Shifting the positions by dr_c = -(G p)_c / rho0_c (eq. 57, G the difference-form SPH gradient,
// ghosts carrying their source's p) changes s_a = 1 - (m_a/rho0_a) sum_b W_ab to first order by
//   ds = K p,  K = (m_a/rho0_a) sum_k D_k R G_k,  R = diag(1/rho0),
// where D_k holds d(sum_b W_ab)/dr_c: F_ab r_ab,k on the diagonal and -F_ab M_b,kk r_ab,k in the
// column of b's source (M_b = diag(flip_x, flip_y): +1, -1 across a wall, 0 held on it). This is
// eq. 59's Taylor expansion without the further step to the approximate Laplacian of eq. 58; unlike
// that Laplacian it keeps a particle's coupling to its own mirror image, which is what moves a
// particle pressed against a wall. Each iteration solves K p = -(s - mean s) with a few matrix-free BiCGSTAB
// iterations (truncated Krylov: the odd-even modes in which K is nearly singular are not amplified),
// and clips each particle's shift at a tenth of the spacing. A step is kept only if it lowers the
// r.m.s. density error (halved up to twice otherwise; if none of these helps, the positions are left
// as they were and the iteration stops), so that the correction never makes the density worse.
#pragma once
#include <vector>

#include "rhs/evaluator.hpp"

namespace arksph {

// The shift of eq. 57 for a potential p: dr_a = -(G p)_a / rho0_a, G the difference-form gradient
// sum_b V_b (p_src(b) - p_a) grad_a W_ab (ghosts carry their source's p).
void correction_shift(const FluidFields& f, const std::vector<double>& p, std::vector<double>& dx,
                      std::vector<double>& dy);
// The first-order change of s_a = 1 - (m_a/rho0_a) sum_b W_ab when every real particle c moves by
// dr_c and each ghost b with it through its mirror map M_b: -(m_a/rho0_a) sum_b F_ab r_ab . (dr_a -
// M_b dr_src(b)). K p is density_change(correction_shift(p)); applied matrix-free.
void density_change(const FluidFields& f, const std::vector<double>& dx, const std::vector<double>& dy,
                    std::vector<double>& ds);

// s_a - mean s, s_a = 1 - (m_a/rho0_a) sum_b W_ab (own term included), for the current fields;
// returns its r.m.s. (Szewc eq. 56).
double density_fluctuation(const FluidFields& f, std::vector<double>& s);
// One Newton direction: K p = -s by a truncated, Jacobi-preconditioned BiCGSTAB (20 iterations at
// most, from p = 0), and (dx, dy) = correction_shift(p), which removes s to first order. Returns the
// Krylov iterations.
int newton_shift(const FluidFields& f, const std::vector<double>& s, std::vector<double>& p, std::vector<double>& dx,
                 std::vector<double>& dy);

struct NewtonCorrectionResult {
  int iterations = 0;        // Newton steps taken
  int rejected = 0;          // steps given up because no fraction of them lowered the error
  long krylov_iterations = 0;
  double error = 0;          // r.m.s. of s about its mean after the last step
};

// Shifts the positions in y (time t) in place; stops after max_iterations steps or once the r.m.s.
// density error is at most `threshold`. error0: the error at entry (fields of y current).
NewtonCorrectionResult correct_density_newton(RhsEvaluator& rhs, double t, double* y, int max_iterations,
                                              double threshold, double spacing);

}  // namespace arksph
