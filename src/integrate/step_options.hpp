// Step-size control shared by both time integrators: ErkOptions (erk_integrator.hpp) and
// ImexOptions (imex_integrator.hpp) extend it with what is specific to their method.
#pragma once
#include <cstddef>
#include <functional>
#include <string>

#include <sundials/sundials_context.h>
#include <sundials/sundials_nvector.h>

namespace arksph {

using RhsFunction = std::function<void(double t, const double* y, double* ydot)>;
// Returns the largest stable step at state y (adaptive mode only).
using StabilityFunction = std::function<double(double t, const double* y)>;
// Names entry i of a right-hand side vector whose value is not finite, for the failure message
// ("particle id 12: acceleration ax = nan").
using EntryDescription = std::function<std::string(std::size_t i, double value)>;

// How the integrator makes its state vector of a given local length, and frees it. Empty (the
// default): a serial vector (serial_vector.hpp). A run over several MPI ranks gives a vector whose
// norms span every rank (distributed/mpi_state_vector.hpp), so that all ranks take the same steps.
struct StateVectorFactory {
  std::function<N_Vector(sunindextype local_length, SUNContext ctx)> make;
  std::function<void(N_Vector)> destroy;
};
// Several ranks: whether `local` holds on any rank (collective; every rank calls it at the same
// point). Empty: one process.
using AnyRank = std::function<bool(bool local)>;

struct StepOptions {
  double fixed_dt = 0;  // > 0: fixed step; 0: adaptive
  double rtol = 1e-4, atol = 1e-8;
  long max_steps = 100000000;
  StabilityFunction stability;  // adaptive mode: h <= stability(t, y)
  double initial_dt = 0;        // adaptive mode: first step (ARKODE does not apply the stability fn to it)
  EntryDescription describe_entry;  // for the message when the right-hand side is not finite (else the index)
  StateVectorFactory state_vector;  // empty: serial
  // Several ranks: a right-hand side that is not finite on one rank is a failed evaluation on all
  // (each rank returns the same flag to ARKODE, which then retries or gives up everywhere).
  AnyRank any_rank;
};

}  // namespace arksph
