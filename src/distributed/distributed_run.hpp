// `arksph run` started by an MPI launcher on several processes (`mpirun -n P arksph run SCENE`):
// the set-up and run loop of run/model_run.hpp with the process strategy of one rank (RankProcess,
// distributed_run.cpp; docs/parallel.md, "Runs over several ranks"):
//   particles   the recursive coordinate bisection (parallel/rcb.hpp) of the particles per cell of
//               side R deals each rank its own (parallel/rank_particles.hpp), sorted by cell as one process
//               sorts its own; at the sync points (method.reorder_every) they migrate to the owners
//               of their positions by a new bisection, and the integrator is re-initialised there
//   f(t, y)     over the rank's particles and their halo (halo_rhs.hpp); the state an MPIPlusX
//               vector with global norms (mpi_state_vector.hpp): every rank takes the same steps
//   projection  over the rank's HaloDomain, the PPE solved by hypre over the ranks (halo_domain.hpp)
//   output      the frame's diagnostics reduced over the ranks, its rows joined on rank 0 or written
//               as a piece per rank (rank_frame.hpp); summary.json with "mpi"
//   checkpoints rank 0 writes the whole state joined from the ranks (parallel/join_by_id.hpp) in the
//               model's particle order; after a scheduled checkpoint the particles are dealt anew
//               from it and a new integrator starts there, as a restart (on any rank count) does.
// A rank may own no particles (it still takes part in every collective call).
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
