// The pressure Poisson equation of the projection schemes (Cummins & Rudman 1999 eq. 19) on one
// rank of a decomposed run (the ParticlePoisson of a rank's domain, distributed/halo_domain.hpp), as
// the projection, the fixed-point density correction and the constrained projection solve it: the
// rows of the rank's particles with global numbers, the halo copies carrying their owners' rows
// (ppe_rows.hpp), solved over the ranks by the solver method.rank_ppe_solver names
// (rank_poisson_solver.hpp) to method.ppe_tolerance. The halo is the caller's: HaloValues gives the halo copies the values of
// their owners (one all-to-all), in the order of the evaluator's points after the rank's own. The
// equation of one particle (a global id fixed for the run) is replaced by P = 0; with rows of given
// P (a free surface, set_given) those rows fix the level instead, and each halo copy takes its
// owner's flag and value along the halo.
//
// The numbering holds while the rank's particles stay: reset() renumbers at the next solve and
// starts the solver cold (a new preconditioner), as after a migration or a new deal.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "distributed_ppe/ppe_rows.hpp"
#include "distributed_ppe/rank_poisson_solver.hpp"
#include "parallel/communicator.hpp"
#include "parallel/rank_particles.hpp"
#include "projection/particle_domain.hpp"

namespace arksph::distributed_ppe {

// Collective. The values *own[k] of the rank's particles at their halo copies (element k).
using HaloValues = std::function<std::vector<std::vector<double>>(const std::vector<const std::vector<double>*>& own)>;

class HaloPoisson : public ParticlePoisson {
 public:
  HaloPoisson(const parallel::Communicator& comm, HaloValues halo_values, const parallel::RankParticles& owned,
              std::int64_t pinned_id, std::unique_ptr<RankPoissonSolver> solver);
  // Collective. Solves L P = source / dt at the evaluator's current fields (f) for the rank's
  // particles (source: their values first). p: the warm start in (resized to the rank's count if it
  // is not), the pinned system's solution out (P = 0 at the pinned particle).
  SolveReport solve(const FluidFields& f, const std::vector<double>& source, double dt, std::vector<double>& p) override;
  std::string name() const override { return solver_->name() == "hypre" ? "hypre-pcg-boomeramg" : "rank-pcg-amg"; }
  // The rows of given P of the rank's particles (at least its owned count of flags and values), for
  // the next solves; empty: none.
  void set_given(DirichletRows given) override { given_ = std::move(given); }
  void reset() override;
  double assembly_seconds() const override { return assembly_seconds_; }

 private:
  const parallel::Communicator& comm_;
  HaloValues halo_values_;
  const parallel::RankParticles& owned_;
  std::int64_t pinned_id_;
  std::unique_ptr<RankPoissonSolver> solver_;
  bool numbered_ = false;
  RowRange range_;
  GlobalRow pinned_row_ = -1;
  std::vector<double> own_rows_;                     // global row of each owned particle
  std::vector<GlobalRow> row_of_;   // owned, then halo copies
  LocalRows rows_;
  DirichletRows given_;       // owned particles
  DirichletRows given_real_;  // owned, then halo copies
  double assembly_seconds_ = 0;
};

}  // namespace arksph::distributed_ppe
