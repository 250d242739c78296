// Linear solvers for the pressure Poisson equation A p = b, registered by name:
//   "klu": SuiteSparse KLU with AMD ordering, the exact reference; the symbolic analysis is reused
//          while the sparsity pattern is unchanged (klu_refactor), redone otherwise.
//   "cg", "cg_ic": Eigen conjugate gradients with a Jacobi or an incomplete-Cholesky preconditioner,
//          warm-started from the previous pressure; for large N (measured on an SPH-like Laplacian: KLU
//          costs ~20 s per factorisation at N = 57,600, CG about 2 s).
//   "cg_amg": CG preconditioned by one V-cycle of smoothed-aggregation AMG (amg_hierarchy.hpp), the
//          hierarchy kept across solves; about 9 iterations a solve where Jacobi CG needs 160-640.
//   "auto": KLU up to 400 unknowns, cg_amg above.
// The matrix handed over is symmetric positive definite (the negated, volume-scaled approximate
// Laplacian with one pinned unknown, see ppe_assembly.hpp).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "core/registry.hpp"

namespace arksph {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

struct SolveReport {
  double relative_residual = 0;  // |A p - b| / |b|
  int iterations = 0;            // 1 for a direct solve
  bool refactored_symbolic = false;
  // Of the solve's time, the set-up of its factorisation or preconditioner: KLU's analysis and
  // (re)factorisation, cg_amg's hierarchy (or the re-pointing of its finest level), hypre's matrix
  // and vectors and BoomerAMG's set-up. 0 for plain CG.
  double setup_seconds = 0;
};

// NumericalFailure (exit 3) for an iterative solver that stopped at its iteration limit above the
// tolerance, naming the key, the iterations and the residual reached.
[[noreturn]] void throw_not_converged(const std::string& solver, double tolerance, const SolveReport& reached);

class PoissonSolver {
 public:
  virtual ~PoissonSolver() = default;
  virtual std::string name() const = 0;
  // Solves A p = b; p holds the initial guess on entry (used by iterative solvers).
  virtual SolveReport solve(const SparseMatrix& A, const std::vector<double>& b, std::vector<double>& p) = 0;
};

// tolerance: relative residual target of iterative solvers.
using PoissonSolverFactory = std::unique_ptr<PoissonSolver> (*)(double tolerance);
const Registry<PoissonSolverFactory>& poisson_solvers();  // method.ppe_solver

std::vector<std::string> poisson_solver_names();
// The solver of the exact operator (C&R eq. 18, not symmetric) for method.ppe_solver = requested:
// KLU for "auto", the requested solver if it takes a matrix that is not symmetric, else empty.
std::string exact_operator_solver(const std::string& requested);
// tolerance: relative residual target of iterative solvers.
std::unique_ptr<PoissonSolver> make_poisson_solver(const std::string& name, double tolerance);

}  // namespace arksph
