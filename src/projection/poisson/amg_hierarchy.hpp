// Aggregation algebraic multigrid for the symmetric positive definite PPE matrix, used as a
// preconditioner (one symmetric V-cycle) by the "cg_amg" Poisson solver.
//
// Sources (the construction follows them; the code is our own):
//   P. Vanek, J. Mandel, M. Brezina, "Algebraic multigrid by smoothed aggregation for second and
//     fourth order elliptic problems", Computing 56 (1996) 179-196: strength of connection
//     |a_ij| >= theta sqrt(a_ii a_jj) (eq. 3.2 with epsilon = theta^2), greedy aggregation in three
//     phases (§3 "Algorithm 1"), piecewise-constant tentative prolongator, smoothed prolongator
//     P = (I - omega D^-1 A) P_tent with omega = (4/3)/rho(D^-1 A) (§4).
//   K. Stüben, "A review of algebraic multigrid", J. Comput. Appl. Math. 128 (2001) 281-309:
//     Galerkin coarse operators A_c = P^T A P (eq. 2.2) and the symmetric V-cycle (§2.1).
//   M. Adams, M. Brezina, J. Hu, R. Tuminaro, "Parallel multigrid smoothing: polynomial versus
//     Gauss-Seidel", J. Comput. Phys. 188 (2003) 593-610: Chebyshev smoothing on D^-1 A targeting
//     the upper part of its spectrum, up to 1.1 x a power-iteration estimate of rho (here the
//     interval [0.33, 1.1] rho); the recurrence is Saad, "Iterative methods for sparse linear
//     systems" (2003), Algorithm 12.1. Degree 1 is damped Jacobi with weight 1/(0.715 rho).
//
// Tuned on the running Re = 1000 cavity at N = 57,600 (CG iterations a solve at 1e-8): theta 0.02 /
// 0.04 gave 14 / 11.5 with Chebyshev degree 1 on every level; degree 3 below the finest level gives
// 8.8 / 9.0 / 9.0 at theta 0.04 / 0.06 / 0.08 (larger theta: a larger level 1, a costlier setup), at
// about one product with the fine matrix more per cycle; degree 2 on the finest level gives 7.2 but
// costs 5 instead of 3 fine products per iteration. Plain (unsmoothed) aggregation halves the error
// per V-cycle at best (test_amg.cpp) and needed 15 (warm) to 30 (cold) iterations in the benchmark.
//
// The same Chebyshev polynomial is applied before and after the coarse correction and the coarsest
// system is solved exactly (dense Cholesky), so the V-cycle is a symmetric positive definite
// operator, as preconditioned CG requires.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "projection/poisson/poisson_solver.hpp"

namespace arksph {

// Compressed sparse rows. Level 0 points into the caller's matrix (a column-major symmetric matrix
// read as rows), coarser levels own their storage.
struct CsrRef {
  int n = 0;
  const int* ptr = nullptr;
  const int* col = nullptr;
  const double* val = nullptr;
};

struct CsrOwned {
  int n = 0;
  std::vector<int> ptr, col;
  std::vector<double> val;
  CsrRef ref() const { return {n, ptr.data(), col.data(), val.data()}; }
};

// Rows below which the solver's loops stay serial: waking the threads costs more than the work.
// Measured on the 50 x 50 ISPH cavity (2,500 rows, 2 threads): CG with its vector loops in
// parallel took 3.3 s of solves to t = 1, against 2.7 s on one thread.
constexpr int kSolverParallelMin = 20000;

// y = A x and r = b - A x, rows in parallel above kSolverParallelMin.
void csr_multiply(const CsrRef& A, const double* x, double* y);
void csr_residual(const CsrRef& A, const double* b, const double* x, double* r);
// The symmetric matrix S (column-major, both triangles stored) read as rows of S^T = S.
CsrRef csr_view(const SparseMatrix& S);

// The preconditioner's matrix of a kernel Laplacian (C&R eq. 19): A without the off-diagonal entries
// below `fraction` of its largest off-diagonal magnitude, each dropped entry added to its row's
// diagonal (row sums kept). The rule reads only |a_ij| and one scale, so a symmetric A gives a
// symmetric result, and a diagonally dominant A a diagonally dominant one. The V-cycle streams its
// finest matrix several times a cycle; with the Wendland C2 kernel at h = 2 dx the entries at
// r >= 1.5 h are 20 of some 45 a row and carry 3 % of the diagonal (measurements:
// bench/RESULTS.md, "sparsified preconditioner").
// A row whose entries are all small on that scale (a spray particle at the edge of its neighbours'
// supports: a zero row sum once every entry is lumped) would lose its diagonal; the diagonal is
// kept at least this fraction of A's, which keeps the result positive definite (a non-negative
// diagonal added to a weakly diagonally dominant symmetric matrix) and changes no row that keeps
// most of its weight (the lattice's rows keep 97 %).
constexpr double kPreconditionerDropBelow = 0.05;
constexpr double kPreconditionerKeptDiagonal = 0.5;
void sparsify(const CsrRef& A, double fraction, CsrOwned& out);
// The same with the scale given: off-diagonal entries below `drop` in magnitude are lumped. Row i's
// diagonal is column i (rows may reference columns beyond A.n: a rank's halo).
void sparsify_below(const CsrRef& A, double drop, CsrOwned& out);
double largest_off_diagonal(const CsrRef& A);

// C = A B (A: A.n rows, B: ncols columns and a row for every column of A), columns unsorted within
// a row. Two passes (count, fill), rows in parallel, one marker array per thread.
CsrOwned csr_product(const CsrRef& A, const CsrRef& B, int ncols);
// A^T: ncols rows.
CsrOwned csr_transpose(const CsrRef& A, int ncols);
// 1 / a_ii of every row (the diagonal at column i); NumericalFailure where it is not positive.
std::vector<double> csr_inverse_diagonal(const CsrRef& A);

struct AmgOptions {
  double theta = 0.04;        // strength threshold, Vanek et al. eq. 3.2
  double theta_decay = 1.0;   // theta on level l: theta x theta_decay^l
  bool smoothed = true;       // smoothed aggregation (else plain piecewise-constant aggregation)
  int chebyshev_degree = 1;   // smoothing steps before and after the coarse correction, finest level
  int coarse_degree = 3;      // the same on the coarser levels
  double omega_scale = 4.0 / 3.0;  // prolongator smoothing: omega = omega_scale / rho(D^-1 A)
  double cheb_lower = 0.3;    // Chebyshev interval [cheb_lower, 1.1] x rho(D^-1 A)
  int max_coarse = 400;       // coarsest size solved by dense Cholesky
  int max_levels = 12;
};

class AmgHierarchy {
 public:
  explicit AmgHierarchy(AmgOptions opt = {}) : opt_(opt) {}
  // Builds aggregates, prolongators and coarse operators for A. A's arrays are read by vcycle():
  // they must outlive its use, or be replaced by rebind_finest().
  void setup(const CsrRef& A);
  // Keeps everything but points the finest level at A (same size): coarse operators stay those of
  // the matrix of the last setup.
  void rebind_finest(const CsrRef& A);
  // z = M r: one V-cycle from a zero initial guess.
  void vcycle(const double* r, double* z) const;
  int levels() const { return static_cast<int>(prolong_.size()) + 1; }
  int size(int level) const { return level == 0 ? A0_.n : coarse_[level - 1].n; }
  long nonzeros(int level) const;
  bool ready() const { return A0_.n > 0; }

 private:
  CsrRef op(int level) const { return level == 0 ? A0_ : coarse_[level - 1].ref(); }
  // Level l's prolongator from its aggregates and operator, and the Galerkin product below it.
  void build_level(int l, int coarse_size);
  void finish();
  void smooth(int level, const double* b, double* x, bool zero_guess) const;
  void cycle(int level, const double* b, double* x) const;

  AmgOptions opt_;
  CsrRef A0_;
  std::vector<std::vector<int>> agg_;  // aggregate of each unknown of level l
  std::vector<CsrOwned> prolong_;  // P_l: size(l) x size(l+1)
  std::vector<CsrOwned> restrict_; // P_l^T
  std::vector<CsrOwned> coarse_;   // A_{l+1} = P_l^T A_l P_l
  std::vector<std::vector<double>> inv_diag_;
  std::vector<double> rho_;        // spectral radius estimate of D^-1 A per level
  Eigen::LLT<Eigen::MatrixXd> coarsest_;
  // Work vectors per level (mutable: the V-cycle is logically const).
  mutable std::vector<std::vector<double>> r_, b_, x_, d_, t_;
};

// Aggregates of the strong-connection graph (Vanek et al. 1996 §3, phases 1-3): agg[i] in
// [0, count). Rows with no off-diagonal strong connection (e.g. the pinned unknown) form singletons.
// Columns at or beyond A.n (the halo of a rank's rows) are left out of the graph.
int aggregate(const CsrRef& A, double theta, std::vector<int>& agg);

}  // namespace arksph
