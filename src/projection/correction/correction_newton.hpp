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
//
// The same iteration runs on one rank of a decomposed run (distributed/halo_domain.hpp)
// through a CorrectionSpan: the rank's own particles come first among the evaluator's real points,
// the halo copies after them; sums and the diagonal's median are taken over all ranks, and a value
// of the own particles reaches the copies from their owners before a pair loop reads it.
#pragma once
#include <functional>
#include <vector>

#include "rhs/evaluator.hpp"

namespace arksph {

// The particles the correction works on and the reductions over them. One process: every real
// particle, sums and medians of its own values, no halo.
struct CorrectionSpan {
  std::size_t own = 0;                                       // the first `own` real points
  std::function<double(double)> sum;                         // of a value over the ranks
  std::function<void(std::vector<double>&)> extend;          // own values -> every real point's (halo copies' from their owners)
  std::function<std::vector<double>(const std::vector<double>&)> gather;  // every rank's own values together
  std::function<bool(bool)> any;                             // true on some rank
};
// The span of one process: the real particles of f.
CorrectionSpan local_span(const FluidFields& f);

// The shift of eq. 57 for a potential p: dr_a = -(G p)_a / rho0_a, G the difference-form gradient
// sum_b V_b (p_src(b) - p_a) grad_a W_ab (ghosts carry their source's p), for the first `count`
// real particles (all by default: a rank's own particles come first, its halo copies after).
void correction_shift(const FluidFields& f, const std::vector<double>& p, std::vector<double>& dx,
                      std::vector<double>& dy, std::size_t count = static_cast<std::size_t>(-1));
// The first-order change of s_a = 1 - (m_a/rho0_a) sum_b W_ab when every real particle c moves by
// dr_c and each ghost b with it through its mirror map M_b: -(m_a/rho0_a) sum_b F_ab r_ab . (dr_a -
// M_b dr_src(b)). K p is density_change(correction_shift(p)); applied matrix-free. For the first
// `count` real particles, as correction_shift.
void density_change(const FluidFields& f, const std::vector<double>& dx, const std::vector<double>& dy,
                    std::vector<double>& ds, std::size_t count = static_cast<std::size_t>(-1));

// s_a - mean s, s_a = 1 - (m_a/rho0_a) sum_b W_ab (own term included), for the current fields;
// returns its r.m.s. (Szewc eq. 56).
double density_fluctuation(const FluidFields& f, std::vector<double>& s);
// The same over a span: s of its own particles, the mean and r.m.s. over every rank's.
double density_fluctuation(const FluidFields& f, const CorrectionSpan& span, std::vector<double>& s);
// One Newton direction: K p = -s by a truncated, Jacobi-preconditioned BiCGSTAB (20 iterations at
// most, from p = 0), and (dx, dy) = correction_shift(p), which removes s to first order. Returns the
// Krylov iterations.
int newton_shift(const FluidFields& f, const std::vector<double>& s, std::vector<double>& p, std::vector<double>& dx,
                 std::vector<double>& dy);
// The same over a span: s, p, dx, dy of its own particles.
int newton_shift(const FluidFields& f, const CorrectionSpan& span, const std::vector<double>& s, std::vector<double>& p,
                 std::vector<double>& dx, std::vector<double>& dy);

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
// The same for a state y of `layout` whose fields `refresh` brings up to date (collective on ranks),
// with `fields` the evaluator's and `span` built for them anew after each refresh.
NewtonCorrectionResult correct_density_newton(const std::function<void(const double*)>& refresh,
                                              const std::function<const FluidFields&()>& fields,
                                              const std::function<CorrectionSpan()>& span, const StateLayout& layout,
                                              double* y, int max_iterations, double threshold, double spacing);

}  // namespace arksph
