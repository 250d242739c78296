// The pressure Poisson equation of the projection schemes (Cummins & Rudman 1999 eq. 19) on one
// rank of a decomposed run, as the projection, the fixed-point density correction and the
// constrained projection solve it: the rows of the rank's particles with global numbers, the halo
// copies carrying their owners' rows (distributed_ppe/ppe_rows.hpp), solved by hypre's
// BoomerAMG-preconditioned PCG (distributed_ppe/hypre_poisson.hpp) to method.ppe_tolerance. The
// equation of one particle (a global id fixed for the run) is replaced by P = 0.
//
// The numbering holds while the rank's particles stay: particles_moved() renumbers at the next solve
// and starts hypre cold (a new hierarchy), as after a migration or a new deal.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "distributed_ppe/hypre_poisson.hpp"
#include "distributed_ppe/ppe_rows.hpp"
#include "parallel/communicator.hpp"

namespace arksph::distributed {

class HaloPoisson {
 public:
  HaloPoisson(const parallel::Communicator& comm, const HaloRhs& f, const RankParticles& owned, std::int64_t pinned_id,
              double tolerance);
  // Collective. Solves L P = source / dt at the evaluator's current fields for the rank's
  // particles (source: one value each). p: the warm start in (resized to the rank's count if it is
  // not), the pinned system's solution out (P = 0 at the pinned particle).
  distributed_ppe::HypreSolveReport solve(const std::vector<double>& source, double dt, std::vector<double>& p);
  // Collective. The level that makes p (the rank's particles) zero-minimum or zero-mean over all ranks.
  double level(const std::vector<double>& p, bool zero_min) const;
  // Collective. The rank's values followed by their halo copies' (their owners' values): one value
  // for each real point of the evaluator.
  std::vector<double> with_halo(const std::vector<double>& own) const;
  // The same for two fields in one all-to-all (the components of a vector).
  std::pair<std::vector<double>, std::vector<double>> with_halo(const std::vector<double>& a,
                                                                const std::vector<double>& b) const;
  void particles_moved();
  double assembly_seconds() const { return assembly_seconds_; }

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
  double assembly_seconds_ = 0;
};

}  // namespace arksph::distributed
