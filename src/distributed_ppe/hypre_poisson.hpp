// The distributed pressure Poisson solve: the rows of all ranks (ppe_rows.hpp) as one hypre ParCSR
// matrix (each rank its contiguous block of rows, written in place), solved by conjugate gradients
// (hypre PCG) preconditioned by one BoomerAMG V-cycle (classical AMG, Ruge & Stueben 1987; HMIS
// coarsening, De Sterck, Yang & Heys 2006, with a distance-two interpolation, as hypre recommends for 2D
// and 3D problems on several ranks; Chebyshev smoothing, hypre_poisson.cpp). The matrix is the one-process "cg_amg"/"klu" matrix, symmetric
// positive definite with the pinned unknown.
//
// The preconditioner's matrix is sparser than the one PCG solves. The rows of the kernel's Laplacian
// (C&R eq. 19) couple a particle to some 45 neighbours out to the support 2h, but the coefficient
// falls as (1 - q/2)^3 for the Wendland C2 kernel: on a square lattice at h = 2 dx the 20 neighbours
// at r >= 1.5 h carry 3 % of the diagonal. Every pass of the V-cycle over the finest level (Chebyshev smoothing before and after,
// the residual) streams the matrix from memory, so the hierarchy is set up on, and the V-cycle runs
// on, the rows without the off-diagonal entries below kDropBelow (0.05) of the largest one over all
// ranks, each dropped entry added to its row's diagonal (the row sums, and so the Laplacian's
// constant null vector away from the pinned row, stay). The rule reads only |a_ij| and a global
// scale, so the sparsified matrix is symmetric as the rows are, and it stays diagonally dominant:
// a symmetric positive definite V-cycle, PCG's requirement. PCG multiplies by the full rows, so the
// solution and its stopping test are those of the full matrix. bench/RESULTS.md compares the two.
//
// Stopping test: |b - A p|_2 <= tolerance |b|_2 (PCG on the two-norm of the residual, not the
// preconditioned one), the test of the one-process iterative solvers with the same tolerance
// (method.ppe_tolerance). A zero source gives p = 0 with no iteration, as cg_amg does.
//
// Reuse across solves, the rule of the one-process cg_amg (projection/poisson/PoissonSolver_AmgCg.cpp): the
// particles move a fraction of a spacing per step, so the BoomerAMG hierarchy set up on one step's
// matrix serves the next ones. A solve that reuses it hands PCG and the V-cycle the new matrix
// (hypre_BoomerAMGSolve takes its finest level from the matrix it is given); the coarse levels,
// interpolation and the Chebyshev smoother's diagonal scaling and eigenvalue bound stay those of
// the set-up matrix: a fixed symmetric preconditioner, so PCG stays valid. The hierarchy is set up anew when a solve needs more
// than kReuseGrowth times the iterations of the first solve after the last set-up (and 2 more), after
// kReuseMax solves, after invalidate() (the rows were numbered anew: migration, a new deal), or
// when any rank's row range changed. Iterations are global, so every rank takes the same decision.
// A kept hierarchy can stop preconditioning: as the particles move, its smoother's eigenvalue bound
// and coarse levels drift from the new matrix, and PCG may break down after an iteration or two,
// far from the tolerance (seen on the N = 57,600 cavity on 2 ranks after 8 reuses, iterations
// falling while the residual grew to 1.9 |b|, which the growth rule cannot see). A solve on a kept
// hierarchy whose true residual ends above kReuseRetryAbove times the tolerance is therefore solved
// again, from the same start, on a hierarchy set up on its own matrix; its iterations and times
// add to the report.
#pragma once
#include <memory>
#include <vector>

#include "distributed_ppe/ppe_rows.hpp"
#include "distributed_ppe/rank_poisson_solver.hpp"
#include "parallel/communicator.hpp"

namespace arksph::distributed_ppe {

using HypreSolveReport = RankSolveReport;

class HyprePoisson final : public RankPoissonSolver {
 public:
  HyprePoisson(const parallel::Communicator& comm, double tolerance);
  ~HyprePoisson() override;
  std::string name() const override { return "hypre"; }
  HyprePoisson(const HyprePoisson&) = delete;
  HyprePoisson& operator=(const HyprePoisson&) = delete;

  // Collective. Solves the system of `rows` (every rank its own); p: the rank's unknowns, the initial
  // guess on entry (resized to zeros if its size differs), the solution on exit (P = 0 at the pinned
  // row). Throws NumericalFailure when hypre reports an error; a solve stopped by the iteration
  // limit (max(200, rows), as cg_amg) returns with its residual in the report, as cg_amg does.
  // rep.refactored_symbolic: BoomerAMG was set up for this solve.
  HypreSolveReport solve(const LocalRows& rows, std::vector<double>& p) override;
  // BoomerAMG and the matrix it was set up on (public for PCG's preconditioner call-back).
  struct Hierarchy;
  // The next solve sets BoomerAMG up anew (call it on every rank).
  void invalidate() override { must_setup_ = true; }
  // hypre's set-ups so far.
  long setups() const override { return setups_; }

 private:
  const parallel::Communicator& comm_;
  double tolerance_;
  std::unique_ptr<Hierarchy> amg_;
  GlobalRow first_ = -1, total_ = -1;  // this rank's row range at the last set-up
  std::size_t rows_ = 0;
  bool must_setup_ = true;
  int solves_since_setup_ = 0, baseline_ = -1;
  long setups_ = 0;
};

}  // namespace arksph::distributed_ppe
