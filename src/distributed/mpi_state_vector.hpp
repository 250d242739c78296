// The ODE state of a run over several MPI ranks: SUNDIALS' MPIPlusX vector around the rank's own
// serial vector (integrate/serial_vector.hpp, the compiled-for-speed operations). Its element-wise
// operations run on the rank's entries; its norms and dot products add the ranks' partial sums
// (MPI_Allreduce), so ARKODE's error norms, step sizes and step acceptance are those of the whole
// state on every rank, and all ranks take the same steps.
#pragma once
#include <mpi.h>

#include "integrate/step_options.hpp"

namespace arksph::distributed {

// For StepOptions::state_vector: makes an MPIPlusX vector of the given local length over `comm`,
// and frees it with its local vector.
StateVectorFactory mpi_state_vector(MPI_Comm comm);

}  // namespace arksph::distributed
