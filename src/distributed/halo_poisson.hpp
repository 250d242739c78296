// The pressure Poisson equation of the projection schemes (Cummins & Rudman 1999 eq. 19) on one
// rank of a decomposed run (the ParticlePoisson of halo_domain.hpp), as the projection, the
// fixed-point density correction and the constrained projection solve it: the rows of the rank's particles with global numbers, the halo
// copies carrying their owners' rows (distributed_ppe/ppe_rows.hpp), solved by hypre's
// BoomerAMG-preconditioned PCG (distributed_ppe/hypre_poisson.hpp) to method.ppe_tolerance. The
// equation of one particle (a global id fixed for the run) is replaced by P = 0; with rows of given
// P (a free surface, set_given) those rows fix the level instead, and each halo copy takes its
// owner's flag and value along the halo.
//
// The numbering holds while the rank's particles stay: reset() renumbers at the next solve and
// starts hypre cold (a new hierarchy), as after a migration or a new deal.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "distributed_ppe/hypre_poisson.hpp"
#include "distributed_ppe/ppe_rows.hpp"
#include "parallel/communicator.hpp"
#include "projection/particle_domain.hpp"

namespace arksph::distributed {

class HaloPoisson : public ParticlePoisson {
 public:
  HaloPoisson(const parallel::Communicator& comm, const HaloRhs& f, const RankParticles& owned, std::int64_t pinned_id,
              double tolerance);
  // Collective. Solves L P = source / dt at the evaluator's current fields (f) for the rank's
  // particles (source: their values first). p: the warm start in (resized to the rank's count if it
  // is not), the pinned system's solution out (P = 0 at the pinned particle).
  SolveReport solve(const FluidFields& f, const std::vector<double>& source, double dt, std::vector<double>& p) override;
  std::string name() const override { return "hypre-pcg-boomeramg"; }
  // The rows of given P of the rank's particles (at least its owned count of flags and values), for
  // the next solves; empty: none.
  void set_given(DirichletRows given) override { given_ = std::move(given); }
  void reset() override;
  double assembly_seconds() const override { return assembly_seconds_; }

 private:
  const parallel::Communicator& comm_;
  const HaloRhs& f_;
  const RankParticles& owned_;
  std::int64_t pinned_id_;
  distributed_ppe::HyprePoisson solver_;
  bool numbered_ = false;
  distributed_ppe::RowRange range_;
  distributed_ppe::GlobalRow pinned_row_ = -1;
  std::vector<double> own_rows_;                     // global row of each owned particle
  std::vector<distributed_ppe::GlobalRow> row_of_;   // owned, then halo copies
  distributed_ppe::LocalRows rows_;
  DirichletRows given_;       // owned particles
  DirichletRows given_real_;  // owned, then halo copies
  double assembly_seconds_ = 0;
};

}  // namespace arksph::distributed
