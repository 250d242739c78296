// A solver of the pressure Poisson equation over the ranks of a decomposed run: the rows every rank
// owns (ppe_rows.hpp), solved together. Two are built, chosen by method.rank_ppe_solver:
//   "amg":   conjugate gradients preconditioned by the smoothed-aggregation V-cycle of the
//            one-process cg_amg, distributed (rank_amg_poisson.hpp);
//   "hypre": hypre's PCG preconditioned by BoomerAMG (hypre_poisson.hpp; builds with hypre only).
// Both stop at |b - A p|_2 <= tolerance |b|_2 and keep their preconditioner across solves by the
// same rule.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "distributed_ppe/ppe_rows.hpp"
#include "parallel/communicator.hpp"
#include "projection/poisson/poisson_solver.hpp"

namespace arksph::distributed_ppe {

// The rule both keep their preconditioner by, the one-process cg_amg's
// (projection/poisson/PoissonSolver_AmgCg.cpp) with its measured constants: set up anew when a
// solve needs more than kReuseGrowth x the iterations of the first solve after the last set-up (and
// 2 more), or after kReuseMax solves; a solve on a kept preconditioner whose true residual ends above
// kReuseRetryAbove x the tolerance is solved again from the same start on a new one.
constexpr double kReuseGrowth = 1.25;
constexpr int kReuseMax = 25;
constexpr double kReuseRetryAbove = 2.0;

struct RankSolveReport : SolveReport {
  double solve_seconds = 0;  // the Krylov iterations (setup_seconds: the matrices and preconditioner)
};

class RankPoissonSolver {
 public:
  virtual ~RankPoissonSolver() = default;
  virtual std::string name() const = 0;
  // Collective. Solves the system of `rows` (every rank its own); p: the rank's unknowns, the
  // initial guess on entry (resized to zeros if its size differs), the solution on exit.
  // rep.refactored_symbolic: the preconditioner was set up for this solve.
  virtual RankSolveReport solve(const LocalRows& rows, std::vector<double>& p) = 0;
  // The next solve sets its preconditioner up anew (call it on every rank): the rows were numbered
  // anew (a migration, a new deal).
  virtual void invalidate() = 0;
  // Preconditioner set-ups so far.
  virtual long setups() const = 0;
};

// The names method.rank_ppe_solver takes in this build ("auto" first), and the solver of one.
std::vector<std::string> rank_poisson_solver_names();
// The solver a name stands for: "auto" is "amg".
std::string resolved_rank_poisson_solver(const std::string& name);
std::unique_ptr<RankPoissonSolver> make_rank_poisson_solver(const std::string& name, const parallel::Communicator& comm,
                                                            double tolerance);

}  // namespace arksph::distributed_ppe
