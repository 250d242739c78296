// The pressure Poisson solve over ranks by conjugate gradients (Saad 2003, Algorithm 9.1)
// preconditioned by one V-cycle of the distributed smoothed-aggregation AMG (rank_amg.hpp): the
// one-process "cg_amg" solver (projection/poisson/PoissonSolver_AmgCg.cpp) with every product and
// sum over the ranks.
//
// As there, the V-cycle runs on the rows without their off-diagonal entries below 0.05 of the
// largest (over all ranks), lumped into the diagonal (amg_hierarchy.hpp, sparsify), and CG multiplies
// by the full rows, so the solution and its stopping test, |b - A p|_2 <= tolerance |b|_2, are the
// matrix's. The hierarchy is kept across solves by the rule of hypre_poisson.hpp (and cg_amg): set
// up anew when a solve needs more than 1.25 times the iterations of the first after the last set-up
// (and 2 more), after 25 solves, after invalidate() or a change of any rank's row count; a solve on
// a kept hierarchy that fails (residual above twice the tolerance, or a preconditioner found not
// positive) is solved again from the same start on a hierarchy set up on its own matrix.
#pragma once
#include <vector>

#include "distributed_ppe/ghost_exchange.hpp"
#include "distributed_ppe/rank_amg.hpp"
#include "distributed_ppe/rank_poisson_solver.hpp"

namespace arksph::distributed_ppe {

// Collective. The rank's rows in local columns (its own rows first, then the ghosts: the other
// ranks' rows they reference, numbered by `halo`, which is built here): a view of rows' offsets and
// values with the columns in `local_col`.
CsrRef rows_in_local_columns(const parallel::Communicator& comm, const LocalRows& rows, GhostExchange& halo,
                             std::vector<int>& local_col);

class RankAmgPoisson final : public RankPoissonSolver {
 public:
  RankAmgPoisson(const parallel::Communicator& comm, double tolerance)
      : comm_(comm), tolerance_(tolerance), amg_(comm) {}
  std::string name() const override { return "amg"; }
  RankSolveReport solve(const LocalRows& rows, std::vector<double>& p) override;
  void invalidate() override { must_setup_ = true; }
  long setups() const override { return setups_; }

 private:
  // PCG from the guess in x_ (own entries); returns whether it reached the tolerance, with its
  // iterations and true relative residual. A preconditioner found not positive ends it (false).
  bool pcg(const double* b, double nb2, int max_it, int& it, double& relative_residual, bool& broke_down);

  const parallel::Communicator& comm_;
  double tolerance_;
  RankAmg amg_;
  GhostExchange halo_;
  std::vector<int> local_col_;  // the rows' columns in the halo's numbering
  CsrOwned M_;                  // the V-cycle's sparsified copy of the rows
  CsrRef A_;
  std::vector<double> x_, r_, z_, d_, q_;
  GlobalRow first_ = -1, total_ = -1;
  bool must_setup_ = true;
  int solves_since_setup_ = 0, baseline_ = -1;
  long setups_ = 0;
};

}  // namespace arksph::distributed_ppe
