// `arksph run` started by an MPI launcher on several processes (`mpirun -n P arksph run SCENE`):
// one run decomposed over the P ranks (docs/parallel.md, "Runs over several ranks").
//
//   set-up      every rank builds the whole model (lattice, initial state) as one process would;
//               the recursive coordinate bisection (parallel/rcb.hpp) of the particles per cell of
//               side R gives each rank its particles (distributed/rank_particles.hpp)
//   stepping    ERKStep on each rank over its own particles, the state an MPIPlusX vector with
//               global norms (mpi_state_vector.hpp): every rank takes the same steps; f(t, y) with
//               the halo (halo_rhs.hpp); the stability limit from the largest speed and
//               acceleration over the ranks
//   sync points at the steps where a one-process run re-sorts its particles (method.reorder_every)
//               the particles migrate to the owners of their positions by a new bisection, and the
//               integrator is re-initialised there (restart_at, as after a re-sort); wall
//               reflections are counted over the ranks and re-initialise every rank
//   projection  isph: the Cummins & Rudman projection after each accepted step over the rank's
//               particles and halo, the PPE solved by hypre over the ranks (halo_domain.hpp)
//   agreement   after every step the ranks agree on failures and signals (rank_verdict.hpp)
//   output      rank 0 gathers the state (gather_state.hpp) and writes what a one-process run
//               writes, summary.json with "mpi": {"ranks", "halo_exchanges", "migrations",
//               "fewest_particles"}; a rank may own no particles (it still takes part in every
//               collective call)
//   checkpoints rank 0 writes checkpoint.h5 as one process does (output.checkpoint_every, at the end,
//               on a signal), the whole state in the model's particle order; a restart
//               (--restart, on any number of ranks) deals the particles from the checkpoint's
//               state. After a scheduled checkpoint the run does what a restart from it does: the
//               particles dealt anew from the whole state (the same bisection and, on each rank,
//               the same order) and a new integrator at that time, so that a restart on as many
//               ranks continues bit for bit as the run that wrote the checkpoint.
//
// What runs only on one process is refused with InputError (exit 2): see check_distributable.
#pragma once
#include "core/scene.hpp"
#include "parallel/communicator.hpp"
#include "run/simulation.hpp"

namespace arksph::distributed {

// InputError (one line, naming the key) for what a run over several ranks does not do yet:
// time.imex, dimension other than 2; under isph and isph-gpps (halo_domain.hpp): the
// orthogonal projection, the density correction with the constrained projection or with its
// KINSOL solver, the exact operator; and builds without hypre.
void check_distributable(const Scene& scene, int ranks);

// Collective over `comm` (size > 1). The RunResult is the same on every rank.
RunResult run_distributed(const Scene& scene, const RunOptions& options, const parallel::Communicator& comm);

}  // namespace arksph::distributed
