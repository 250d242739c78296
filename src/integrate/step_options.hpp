// Step-size control shared by both time integrators: ErkOptions (erk_integrator.hpp) and
// ImexOptions (imex_integrator.hpp) extend it with what is specific to their method.
#pragma once
#include <cstddef>
#include <functional>
#include <string>

namespace arksph {

using RhsFunction = std::function<void(double t, const double* y, double* ydot)>;
// Returns the largest stable step at state y (adaptive mode only).
using StabilityFunction = std::function<double(double t, const double* y)>;
// Names entry i of a right-hand side vector whose value is not finite, for the failure message
// ("particle id 12: acceleration ax = nan").
using EntryDescription = std::function<std::string(std::size_t i, double value)>;

struct StepOptions {
  double fixed_dt = 0;  // > 0: fixed step; 0: adaptive
  double rtol = 1e-4, atol = 1e-8;
  long max_steps = 100000000;
  StabilityFunction stability;  // adaptive mode: h <= stability(t, y)
  double initial_dt = 0;        // adaptive mode: first step (ARKODE does not apply the stability fn to it)
  EntryDescription describe_entry;  // for the message when the right-hand side is not finite (else the index)
};

}  // namespace arksph
