// ERKStep's own cost per step, without a right-hand side worth the name (y' = -y), on the state size of
// the 50 x 50 WCSPH cavity (5 x 2500 entries): Debian's serial N_Vector (built at -O0) against the
// same vector with the operations of integrate/serial_vector.cpp. Heun-Euler, adaptive with a
// stability limit, as the cavity case runs. items_per_second = steps per second.
#include <arkode/arkode_erkstep.h>
#include <benchmark/benchmark.h>
#include <nvector/nvector_serial.h>

#include "integrate/serial_vector.hpp"

namespace arksph::bench {
namespace {

int decay(double, N_Vector y, N_Vector ydot, void*) {
  const sunindextype n = NV_LENGTH_S(y);
  const double* a = NV_DATA_S(y);
  double* d = NV_DATA_S(ydot);
  for (sunindextype i = 0; i < n; ++i) d[i] = -a[i];
  return 0;
}

int stability(N_Vector, double, double* h, void*) {
  *h = 1e-3;
  return 0;
}

void BM_ErkStepOverhead(benchmark::State& state, bool fast_ops) {
  SUNContext ctx;
  SUNContext_Create(nullptr, &ctx);
  const sunindextype n = 12500;
  N_Vector y = fast_ops ? new_serial_vector(n, ctx) : N_VNew_Serial(n, ctx);
  N_VConst(1.0, y);
  void* mem = ERKStepCreate(decay, 0.0, y, ctx);
  ERKStepSetTableNum(mem, ARKODE_HEUN_EULER_2_1_2);
  ERKStepSStolerances(mem, 1e-2, 1e-4);
  ERKStepSetStabilityFn(mem, stability, nullptr);
  ERKStepSetMaxNumSteps(mem, 0);
  double t = 0;
  for (auto _ : state) ERKStepEvolve(mem, 1e9, y, &t, ARK_ONE_STEP);
  state.SetItemsProcessed(state.iterations());
  ERKStepFree(&mem);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
}

BENCHMARK_CAPTURE(BM_ErkStepOverhead, library_ops, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ErkStepOverhead, fast_ops, true)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace arksph::bench
