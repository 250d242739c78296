// The distributed pressure Poisson solve: the rows of all ranks (ppe_rows.hpp) as one hypre ParCSR
// matrix (HYPRE_IJMatrix, each rank its contiguous block of rows), solved by conjugate gradients
// (hypre PCG) preconditioned by one BoomerAMG V-cycle (classical AMG, Ruge & Stueben 1987; HMIS
// coarsening and extended+i interpolation, De Sterck, Yang & Heys 2006, as hypre recommends for 2D
// and 3D problems on several ranks; Chebyshev smoothing, hypre_poisson.cpp). The matrix is the one-process "cg_amg"/"klu" matrix, symmetric
// positive definite with the pinned unknown.
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
// than kGrowth times the iterations of the first solve after the last set-up (and 2 more), after
// kMaxReuse solves, after invalidate() (the rows were numbered anew: migration, a new deal), or
// when any rank's row range changed. Iterations are global, so every rank takes the same decision.
#pragma once
#include <memory>
#include <vector>

#include "distributed_ppe/ppe_rows.hpp"
#include "parallel/communicator.hpp"
#include "projection/poisson/poisson_solver.hpp"

namespace arksph::distributed_ppe {

struct HypreSolveReport : SolveReport {
  double solve_seconds = 0;  // PCG iterations
};

class HyprePoisson {
 public:
  HyprePoisson(const parallel::Communicator& comm, double tolerance);
  ~HyprePoisson();
  HyprePoisson(const HyprePoisson&) = delete;
  HyprePoisson& operator=(const HyprePoisson&) = delete;

  // Collective. Solves the system of `rows` (every rank its own); p: the rank's unknowns, the initial
  // guess on entry (resized to zeros if its size differs), the solution on exit (P = 0 at the pinned
  // row). Throws NumericalFailure when hypre reports an error; a solve stopped by the iteration
  // limit (max(200, rows), as cg_amg) returns with its residual in the report, as cg_amg does.
  // rep.refactored_symbolic: BoomerAMG was set up for this solve.
  HypreSolveReport solve(const LocalRows& rows, std::vector<double>& p);
  // The next solve sets BoomerAMG up anew (call it on every rank).
  void invalidate() { must_setup_ = true; }
  // hypre's set-ups so far.
  long setups() const { return setups_; }

 private:
  struct Hierarchy;  // BoomerAMG and the matrix it was set up on
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
