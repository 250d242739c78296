// The distributed pressure Poisson solve: the rows of all ranks (ppe_rows.hpp) as one hypre ParCSR
// matrix (HYPRE_IJMatrix, each rank its contiguous block of rows), solved by conjugate gradients
// (hypre PCG) preconditioned by one BoomerAMG V-cycle (classical AMG, Ruge & Stueben 1987; HMIS
// coarsening and extended+i interpolation, De Sterck, Yang & Heys 2006, as hypre recommends for 2D
// and 3D problems on several ranks). The matrix is the one-process "cg_amg"/"klu" matrix, symmetric
// positive definite with the pinned unknown.
//
// Stopping test: |b - A p|_2 <= tolerance |b|_2 (PCG on the two-norm of the residual, not the
// preconditioned one), the test of the one-process iterative solvers with the same tolerance
// (method.ppe_tolerance). A zero source gives p = 0 with no iteration, as cg_amg does.
// The BoomerAMG hierarchy is set up anew at every solve (the matrix changes every step).
#pragma once
#include <vector>

#include "distributed_ppe/ppe_rows.hpp"
#include "parallel/communicator.hpp"
#include "projection/poisson_solver.hpp"

namespace arksph::distributed_ppe {

struct HypreSolveReport : SolveReport {
  double setup_seconds = 0;  // matrix and vectors handed to hypre, BoomerAMG set up
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
  HypreSolveReport solve(const LocalRows& rows, std::vector<double>& p);

 private:
  const parallel::Communicator& comm_;
  double tolerance_;
};

}  // namespace arksph::distributed_ppe
