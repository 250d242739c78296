// SUNDIALS serial N_Vector with compiled-for-speed operations.
//
// Debian 12's libsundials_nvecserial (6.4.1) is built without optimisation (-O0: every loop keeps
// its index and sum on the stack). Its O(n) operations run at 2-9 ns per entry, and ERKStep spends
// them on every step: in the 50 x 50 cavity they were 10 % of a WCSPH run, more than the neighbour
// search after its rebuild was made cheap (bench/RESULTS.md, "ERKStep overhead").
//
// new_serial_vector makes an ordinary serial vector (same content layout, so N_VGetArrayPointer,
// N_VClone and SUNLinSol_KLU work unchanged) and replaces the pointers of its O(n) operations with
// the ones in serial_vector.cpp. ARKODE and KINSOL clone their work vectors from the one they are
// given, and a clone copies the operation table, so every vector of the integrator gets them.
//
// The replacements do exactly the arithmetic of nvector_serial.c, in the same order and with the
// same special cases (N_VLinearSum with a == b computes a (x + y), not a x + a y): runs are bit for
// bit those with the library's own operations (tests/unit/test_serial_vector.cpp checks each operation
// against the library). The fused and vector-array operations stay unset, as in N_VNew_Serial, so
// ARKODE composes them from these.
#pragma once
#include <sundials/sundials_context.h>
#include <sundials/sundials_nvector.h>

namespace arksph {

// N_VNew_Serial(n, ctx) with the operations replaced; null if the allocation fails.
N_Vector new_serial_vector(sunindextype n, SUNContext ctx);

// Replaces the O(n) operations of an existing serial vector (its clones made afterwards inherit them).
void use_fast_serial_ops(N_Vector v);

}  // namespace arksph
