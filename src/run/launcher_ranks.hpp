// The processes of an MPI launch (mpirun, mpiexec, srun with PMI) as the launcher's environment
// describes them, read without MPI: `arksph run` under a launcher of several processes runs
// decomposed over them (distributed/distributed_run.hpp), and `arksph batch` shares its runs among
// them (study/batch_ranks.hpp).
#pragma once
#include <string>

namespace arksph {

struct LauncherRanks {
  int rank = 0, size = 1;  // size 1: not started by a launcher (or by one with a single process)
  int local_size = 1;      // processes of the launch on this host
  std::string launch;      // the same for every rank of one launch, different for another launch
};

// From OMPI_COMM_WORLD_RANK/SIZE (Open MPI) or PMI_RANK/SIZE (MPICH's Hydra and other PMI
// launchers); the launch id from PMIX_NAMESPACE, OMPI_MCA_ess_base_jobid or PMI_KVSNAME, else the
// host and parent pid (the launcher's local daemon). InputError for an inconsistent rank/size.
LauncherRanks launcher_ranks_from_environment();

// Removes the rank and size variables read above from this process's environment: a batch's child
// runs are single processes, and `arksph run` under a launcher of several processes runs decomposed
// over them (docs/parallel.md).
void forget_launcher_ranks();

// This host's name.
std::string host_name();

}  // namespace arksph
