#include "distributed/mpi_state_vector.hpp"

#include <nvector/nvector_mpiplusx.h>

#include "integrate/serial_vector.hpp"

namespace arksph::distributed {

StateVectorFactory mpi_state_vector(MPI_Comm comm) {
  StateVectorFactory f;
  f.make = [comm](sunindextype n, SUNContext ctx) -> N_Vector {
    N_Vector local = new_serial_vector(n, ctx);
    if (!local) return nullptr;
    N_Vector v = N_VMake_MPIPlusX(comm, local, ctx);
    if (!v) N_VDestroy(local);
    return v;
  };
  // N_VMake_MPIPlusX does not own its local vector (ARKODE's clones own theirs).
  f.destroy = [](N_Vector v) {
    N_Vector local = N_VGetLocalVector_MPIPlusX(v);
    N_VDestroy(v);
    if (local) N_VDestroy(local);
  };
  return f;
}

}  // namespace arksph::distributed
